"""Templates only (`student.html`, `described.html`): the kind is `problems.kinds.lagrangian`."""
