"""Multiple choice: the answer names one of a few stated choices, by its letter (`B`, `b)`, `(b)`) or
by its whole text; exactly one choice is right, and a wrong one may carry its own feedback."""

from __future__ import annotations

import re
from dataclasses import dataclass
from string import ascii_uppercase

from physics.errors import ParseError, SpecError
from physics.mathinput import InputLimits
from physics.verdict import InputProblem, Judgement, Preview, ReadAs, Reason, Verdict

MAX_CHOICES = len(ascii_uppercase)
_LETTER = re.compile(r"^\(?\s*([A-Za-z])\s*[.)]?$")
CORRECT_FEEDBACK = "Correct."
WRONG_FEEDBACK = "That is not the right choice."


def label(index: int) -> str:
    """The letter a choice is shown and answered by: A, B, C, …"""
    return ascii_uppercase[index]


def _plain(text: str) -> str:
    return " ".join(text.split()).casefold()


@dataclass(frozen=True)
class Choice:
    text: str
    feedback: str | None = None  # shown when this (wrong) choice is picked


@dataclass(frozen=True)
class ChoiceQuestion:
    """A physics.checking.Question: plain data, carried whole into a worker."""

    choices: tuple[Choice, ...]
    correct: int  # index into `choices`

    def __post_init__(self) -> None:
        if not 2 <= len(self.choices) <= MAX_CHOICES:
            raise SpecError(f"give from 2 to {MAX_CHOICES} choices", ("choices",))
        if not 0 <= self.correct < len(self.choices):
            raise SpecError("the right choice must be one of the choices", ("choices",))

    def pick(self, answer: str) -> int:
        """The index of the choice `answer` names; ParseError when it names none."""
        text = answer.strip()
        letter = _LETTER.match(text)
        if letter is not None:
            index = ascii_uppercase.find(letter.group(1).upper())
            if index < len(self.choices):
                return index
        for index, choice in enumerate(self.choices):
            if _plain(choice.text) == _plain(text):
                return index
        last = label(len(self.choices) - 1)
        raise ParseError(f"Answer with the letter of one choice, A to {last}.", 0)

    def grade(self, answer: str, limits: InputLimits | None = None) -> Verdict:
        try:
            index = self.pick(answer)
        except ParseError as error:
            return Verdict.invalid(error)
        read_as = _read_as(index)
        if index == self.correct:
            return Verdict.graded(Judgement(True, Reason.EQUIVALENT, CORRECT_FEEDBACK), read_as)
        feedback = self.choices[index].feedback
        if feedback is not None:
            return Verdict.graded(Judgement(False, Reason.KNOWN_MISTAKE, feedback), read_as)
        return Verdict.graded(Judgement(False, Reason.WRONG_VALUE, WRONG_FEEDBACK), read_as)

    def read(self, answer: str, limits: InputLimits | None = None) -> Preview:
        try:
            return Preview(_read_as(self.pick(answer)), None)
        except ParseError as error:
            return Preview(None, InputProblem(error.message, error.position))


def _read_as(index: int) -> ReadAs:
    return ReadAs(text=label(index), latex=rf"\text{{{label(index)}}}")
