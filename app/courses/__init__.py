"""Courses: staff, rosters, sign-in links, assignments with due dates and late policies, the gradebook.

records.py     what the course store returns (plain frozen dataclasses) and its errors
models.py      the tables (only app/storage/sql_courses.py touches them)
policy.py      due dates, late penalties, statuses and solution release: pure functions of the records
gradebook.py   students x assignments from the submissions, penalties applied; its CSV
access.py      who may see what: a course's staff, a student's assigned problems, uploads' owners
sessions.py    personal sign-in links, join codes, students' session cookies, "view as a student"
roster_csv.py  reading a roster CSV (id, name, email), every bad line reported at once
service.py     the gradebook and a student's standing read from the stores and the catalog
passback.py    an assignment's total for its LMS line items (queued as each answer is filed)
"""
