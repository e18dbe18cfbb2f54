import pytest

from physics.errors import SpecError, SpecErrors
from physics.wording import counted, the_counted


@pytest.mark.parametrize(
    ("count", "noun", "plural", "expected"),
    [
        (1, "problem", None, "1 problem"),
        (2, "problem", None, "2 problems"),
        (0, "failure", None, "0 failures"),
        (1, "child", "children", "1 child"),
        (3, "child", "children", "3 children"),
    ],
)
def test_counted_agrees_the_noun_with_the_count(count, noun, plural, expected):
    assert counted(count, noun, plural) == expected


@pytest.mark.parametrize(("count", "head"), [(1, "1 error:"), (2, "2 errors:")])
def test_spec_errors_count_their_errors_in_words(count, head):
    errors = SpecErrors([SpecError(f"fault {i}", ("model",)) for i in range(count)])
    assert str(errors).startswith(head + "\n")


@pytest.mark.parametrize(
    ("count", "noun", "expected"), [(1, "equation", "the equation"), (2, "equation", "the 2 equations")]
)
def test_the_counted_leaves_out_a_count_of_one(count, noun, expected):
    assert the_counted(count, noun) == expected
