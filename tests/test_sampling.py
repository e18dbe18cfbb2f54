"""The daily sample of like cases: the same for a seed, new for another, every case when asked."""

from __future__ import annotations

import pytest

from tests.sampling import ALL_ENV, SEED_ENV, sample_marked, sampled

CASES = [f"problem-{n}" for n in range(49)]


def test_a_seed_draws_the_same_sample_in_the_cases_order(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ALL_ENV, raising=False)
    monkeypatch.setenv(SEED_ENV, "7")
    first = sampled(CASES, 16, "pages")
    assert first == sampled(CASES, 16, "pages")
    assert len(first) == 16 and first == sorted(first, key=CASES.index)


def test_each_day_draws_anew_and_a_few_days_cover_every_case(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ALL_ENV, raising=False)
    covered: set[str] = set()
    samples = []
    for day in range(739_000, 739_030):
        monkeypatch.setenv(SEED_ENV, str(day))
        samples.append(tuple(sampled(CASES, 16, "pages")))
        covered.update(samples[-1])
    assert len(set(samples)) == len(samples)
    assert covered == set(CASES)


def test_two_checks_draw_their_own_samples(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(ALL_ENV, raising=False)
    monkeypatch.setenv(SEED_ENV, "7")
    assert sampled(CASES, 16, "pages") != sampled(CASES, 16, "views")


@pytest.mark.parametrize("k", [16, 49, 60])
def test_every_case_runs_when_asked_or_when_there_are_few(monkeypatch: pytest.MonkeyPatch, k: int) -> None:
    monkeypatch.setenv(ALL_ENV, "1")
    assert sampled(CASES, k, "pages") == CASES
    monkeypatch.delenv(ALL_ENV)
    assert (sampled(CASES, k, "pages") == CASES) == (k >= len(CASES))


def test_a_sample_mark_keeps_k_cases_of_each_marked_test_and_every_unmarked_one(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.delenv(ALL_ENV, raising=False)
    monkeypatch.setenv(SEED_ENV, "7")
    marks = {"slow_table": 2, "other_table": 1}
    items = [f"{test}[{case}]" for test in ("slow_table", "plain", "other_table") for case in "abcd"]

    def k_of(item: str) -> int | None:
        return marks.get(item.split("[")[0])

    kept = sample_marked(items, k_of, lambda item: item.split("[")[0])
    assert [item for item in kept if item.startswith("plain")] == [f"plain[{case}]" for case in "abcd"]
    assert len([item for item in kept if item.startswith("slow_table")]) == 2
    assert len([item for item in kept if item.startswith("other_table")]) == 1
    assert kept == sorted(kept, key=items.index)
    monkeypatch.setenv(ALL_ENV, "1")
    assert sample_marked(items, k_of, lambda item: item.split("[")[0]) == items
