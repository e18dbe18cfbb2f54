"""The upload page's preview lists the errors of every vetting stage at once, each with its path."""

from __future__ import annotations

import yaml
from fastapi.testclient import TestClient

from app.instructor.router import yaml_text
from problems.loader import BANK_DIR
from tests.instructor.conftest import csrf_of


def test_preview_lists_a_shape_fault_beside_a_derivation_fault(signed_in: TestClient):
    doc = yaml.safe_load((BANK_DIR / "atwood" / "problem.yaml").read_text())
    doc["model"] = yaml.safe_load((BANK_DIR / "atwood" / "model.yaml").read_text())
    doc["id"] = "my-broken-atwood"
    doc["parts"][2]["tolerance"] = {"rel": -0.5}
    doc["model"]["quantities"]["wobble"] = {"angular_frequency": "s"}
    token = csrf_of(signed_in.get("/instructor/problems/new").text)
    response = signed_in.post(
        "/instructor/problems/new", data={"csrf": token, "source": yaml_text(doc), "action": "preview"}
    )
    assert response.status_code == 422
    assert '<code class="path">parts[2].tolerance.rel</code>' in response.text
    assert '<code class="path">model.quantities.wobble</code>' in response.text
    # the self-test that could not run is a note beside the two faults, not a third error
    faults, _, notes = response.text.partition('<ul class="not-run"')
    assert "2 errors; 1 stage could not run: nothing was saved</h2>" in faults
    assert "not self-tested" not in faults
    assert '<code class="path">parts</code>' in notes and "not self-tested" in notes
