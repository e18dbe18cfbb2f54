"""The instructor pages (`/instructor/…`): problems, uploads, class results, LMS delivery problems."""
