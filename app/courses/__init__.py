"""Courses: staff, rosters, sign-in links, assignments with due dates and late policies, the gradebook.

records.py   what the course store returns (plain frozen dataclasses) and its errors
models.py    the tables (only app/storage/sql_courses.py touches them)
policy.py    due dates, late penalties, statuses and solution release: pure functions of the records
gradebook.py students x assignments from the submissions, penalties applied; its CSV
access.py    who may see what: a course's staff, a student's assigned problems
"""
