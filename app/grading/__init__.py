"""Bounded grading: every check runs in a killable worker process under a wall-clock and memory limit."""
