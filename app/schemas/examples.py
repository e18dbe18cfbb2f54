"""A working example of every request body in the OpenAPI document, so that /docs "Try it out" sends
something the service accepts (tests/api/test_openapi_examples.py sends each one).

Each is a mapping `name -> {"summary", "value"}`, as FastAPI's `openapi_examples` takes it; an upload's
are put in the route's `openapi_extra` by hand, since it reads its body itself.
"""

from __future__ import annotations

from typing import Any

import yaml

Examples = dict[str, dict[str, Any]]

CHECK: Examples = {
    "symbolic": {
        "summary": "A symbolic answer with Greek letters and implied products",
        "value": {
            "kind": "symbolic",
            "answer": "-m g sin(θ)cos(θ)/(M + m sin^2 θ)",
            "expected": "-m*g*sin(theta)*cos(theta)/(M + m*sin(theta)**2)",
            "symbols": {
                "m": {"dimension": "kg"},
                "M": {"dimension": "kg"},
                "g": {"dimension": "m/s^2"},
                "theta": {"dimension": "1", "range": [0, "pi/2"]},
            },
        },
    },
    "numeric": {
        "summary": "A number with units, within 1 %",
        "value": {
            "kind": "numeric",
            "answer": "4.58 m/s^2",
            "expected": 4.5807,
            "units": "m/s^2",
            "tolerance": {"rel": 0.01},
        },
    },
    "choice": {
        "summary": "One of several choices",
        "value": {
            "kind": "choice",
            "answer": "b",
            "choices": [
                {"text": "It speeds up", "feedback": "Friction acts against the motion."},
                {"text": "It slows down", "correct": True},
                {"text": "Its speed stays the same"},
            ],
        },
    },
}

PROBLEM_ID = {"atwood": {"summary": "The bank's Atwood machine", "value": "atwood"}}
PART_ID = {"acceleration": {"summary": "Its symbolic part", "value": "acceleration"}}

SUBMISSION: Examples = {
    "own": {
        "summary": "A student's answer (a student key, or an instructor trying the problem)",
        "value": {"answer": "(m2 - m1) g/(m1 + m2)"},
    },
    "for a student": {
        "summary": "An instructor key filing a student's answer",
        "value": {"answer": "g (m2 - m1)/(m1 + m2)", "student": "s-1024"},
    },
}

PREVIEW: Examples = {
    "typing": {"summary": "How a half-typed answer reads", "value": {"answer": "(m2 - m1) g/(m1 + m2"}},
    "read": {"summary": "How a whole answer reads", "value": {"answer": "(m2-m1)g/(m1+m2)"}},
}

# The bank's Atwood machine under an id of the uploader's own.
UPLOADED_ID = "my-atwood"
UPLOADED_PROBLEM_ID = {"mine": {"summary": "A problem the key uploaded", "value": UPLOADED_ID}}
_ATWOOD: dict[str, Any] = {
    "id": UPLOADED_ID,
    "title": "Atwood machine",
    "topics": ["newton's laws", "pulleys"],
    "statement": (
        "Two masses $m_1$ and $m_2$ hang on either side of a light frictionless pulley. Count "
        "accelerations positive when $m_2$ moves down; write $m_1$ as `m1` and $m_2$ as `m2`.\n\n"
        "For the numerical part: $m_1$ = {m1}, $m_2$ = {m2}, $g$ = {g}."
    ),
    "symbols": {
        "m1": {"meaning": "mass on the left", "dimension": "kg"},
        "m2": {"meaning": "mass on the right", "dimension": "kg"},
        "g": {"meaning": "acceleration due to gravity", "dimension": "m/s^2"},
    },
    "given": {
        "m1": {"min": 0.2, "max": 2.0, "unit": "kg", "sigfigs": 2},
        "m2": {"min": 0.2, "max": 2.0, "unit": "kg", "sigfigs": 2},
        "g": {"min": 9.81, "max": 9.81, "unit": "m/s^2"},
    },
    "parts": [
        {
            "id": "acceleration",
            "kind": "symbolic",
            "prompt": "Find the acceleration of $m_2$, positive downward.",
            "answer": "(m2 - m1)*g/(m1 + m2)",
        },
        {
            "id": "acceleration_numeric",
            "kind": "numeric",
            "prompt": "Using the values given, find the acceleration of $m_2$ in m/s².",
            "of": "acceleration",
            "units": "m/s^2",
        },
    ],
    "model": {
        "coordinates": ["s"],
        "bodies": {
            "m1": {"mass": "m1", "position": {"y": "s"}},
            "m2": {"mass": "m2", "position": {"y": "-s"}},
        },
        "gravity": "g",
        "elements": {
            "string": {
                "kind": "pulley",
                "ends": [{"body": "m1", "pulls": "up"}, {"body": "m2", "pulls": "up"}],
            }
        },
        "quantities": {"acceleration": {"acceleration": "s"}},
    },
}
UPLOAD_JSON: Examples = {"atwood": {"summary": "An Atwood machine with its model", "value": _ATWOOD}}
UPLOAD_YAML: Examples = {
    "atwood": {
        "summary": "The same in YAML",
        "value": yaml.safe_dump(_ATWOOD, sort_keys=False, allow_unicode=True),
    }
}


# ---- courses (app/routers/courses.py): ids as a fresh service gives them to the examples above ------

COURSE: Examples = {
    "course": {
        "summary": "A course, its dates shown in the school's zone",
        "value": {"title": "Mechanics 101", "timezone": "Europe/Paris"},
    }
}
COURSE_ID = {"first": {"summary": "The first course made", "value": 1}}
ASSIGNMENT_ID = {"first": {"summary": "The first assignment made", "value": 1}}
ROSTER_CSV = "id,name,email\ns001,Ada Lovelace,ada@uni.example\ns002,Émilie du Châtelet,emilie@uni.example\n"
ROSTERED_STUDENT = {
    "rostered": {
        "summary": "A student imported with the roster, as their work is filed",
        "value": "course:1:s001",
    }
}
STAFF: Examples = {
    "ta": {
        "summary": "A teaching assistant, by their instructor key's id",
        "value": {"member": "key:1", "role": "ta", "name": "Sam (TA)"},
    }
}
SIGN_IN_LINKS: Examples = {
    "everyone": {"summary": "A link for every student on the roster", "value": {}},
    "some": {
        "summary": "New links for two students",
        "value": {"students": ["course:1:s001", "course:1:s002"]},
    },
}
JOIN_CODE: Examples = {"on": {"summary": "A new join code", "value": {"enabled": True}}}
ASSIGNMENT: Examples = {
    "homework": {
        "summary": "Two problems due in a week, 10 % off per late day up to half",
        "value": {
            "title": "Homework 1: Atwood machines",
            "problems": ["atwood", "atwood-massive-pulley"],
            "opens_at": "2026-09-01T08:00:00+02:00",
            "due_at": "2026-09-08T23:59:00+02:00",
            "late": {"kind": "penalty", "per_day": 0.1, "limit": 0.5},
            "max_attempts": 5,
            "solutions": "after_due",
        },
    }
}
EXTENSION: Examples = {
    "week": {"summary": "A week more for one student", "value": {"due_at": "2026-09-15T23:59:00+02:00"}},
    "regrade": {
        "summary": "A week more, and no late penalty on the answers already given",
        "value": {"due_at": "2026-09-15T23:59:00+02:00", "regrade_earlier": True},
    },
}


def json_body(named: Examples) -> dict[str, Any]:
    """A route's `openapi_extra` giving its JSON body these examples (FastAPI leaves out the examples
    of a body parameter declared with `embed=True`)."""
    return {"requestBody": {"content": {"application/json": {"examples": named}}}}


SHARE: Examples = {
    "share": {"summary": "Share the upload with every instructor's bank", "value": {"shared": True}}
}
