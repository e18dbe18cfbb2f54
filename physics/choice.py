"""Multiple choice: the answer names one of a few stated choices, by its letter (`B`, `b)`, `(b)`,
`option b`) or by its whole text (or both, as a list prints them: `b) Down the slope`); exactly one
choice is right, and a wrong one may carry its own feedback."""

from __future__ import annotations

import re
from dataclasses import dataclass
from string import ascii_uppercase

from physics.characters import fullwidth_as_ascii, without_zero_width
from physics.errors import ParseError, SpecError
from physics.mathinput import InputLimits
from physics.verdict import InputProblem, Judgement, Preview, ReadAs, Reason, Verdict

MAX_CHOICES = len(ascii_uppercase)
_LETTER = re.compile(r"^\(?\s*([A-Za-z])\s*[.)]?$")
# A letter as a sentence says it: `option b`, `Choice B`, `answer b`
_SAID_LETTER = re.compile(r"^(?:option|choice|answer)\s+\(?\s*([A-Za-z])\s*[.)]?$", re.IGNORECASE)
# A letter with its choice's text, as a list prints it: `a) Up the slope`, `B - Down the slope`
_LETTER_AND_TEXT = re.compile(r"^\(?\s*([A-Za-z])\s*(?:[.):]|\s[-–—]|-)\s*(.+)$")
CORRECT_FEEDBACK = "Correct."
WRONG_FEEDBACK = "That is not the right choice."


def label(index: int) -> str:
    """The letter a choice is shown and answered by: A, B, C, …"""
    return ascii_uppercase[index]


def _plain(text: str) -> str:
    """The text as compared: spacing, letter case and a closing full stop aside."""
    return " ".join(text.split()).casefold().removesuffix(".").rstrip()


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
        visible = without_zero_width(answer)
        text = fullwidth_as_ascii(answer if visible is None else visible.text).strip()
        letter = _LETTER.match(text)
        if letter is not None:
            index = ascii_uppercase.find(letter.group(1).upper())
            if index < len(self.choices):
                return index
        by_text = self._by_text(text)
        if by_text is not None:
            return by_text
        said = _SAID_LETTER.match(text)
        if said is not None:
            index = ascii_uppercase.find(said.group(1).upper())
            if index < len(self.choices):
                return index
        last = label(len(self.choices) - 1)
        with_text = _LETTER_AND_TEXT.match(text)
        if with_text is not None:
            index = ascii_uppercase.find(with_text.group(1).upper())
            named = self._by_text(with_text.group(2))
            if named is not None and named == index:
                return index
            if named is not None:  # `a) Down the slope`: which one?
                raise ParseError(
                    f'{label(index)} is not the choice "{self.choices[named].text}" ({label(named)}): '
                    f"answer with the letter of one choice, A to {last}.",
                    0,
                )
        raise ParseError(f"Answer with the letter of one choice, A to {last}.", 0)

    def _by_text(self, text: str) -> int | None:
        for index, choice in enumerate(self.choices):
            if _plain(choice.text) == _plain(text):
                return index
        return None

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
