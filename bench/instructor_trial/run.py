"""Trial as a new instructor: vet each problem file; per symbolic part: derived?, agreeing methods, simulated?

Usage: .venv/bin/python bench/instructor_trial/run.py bench/instructor_trial [name-filter]   (from the project root)
"""

import pathlib
import sys
import time

import yaml

from problems.modelinfo import derive_doc
from problems.symbols import symbol_table
from problems.vetting import vet_document


def simulated(raw: object, quantity: str) -> bool:
    sims = getattr(raw, "simulation", None) or {}
    return quantity in sims


def main() -> None:
    folder = pathlib.Path(sys.argv[1])
    pattern = sys.argv[2] if len(sys.argv) > 2 else ""
    total = good = 0
    for path in sorted(folder.glob("*.yaml")):
        if pattern not in path.stem:
            continue
        source = path.read_text()
        parts = [p for p in yaml.safe_load(source)["parts"] if p.get("kind") == "symbolic"]
        total += len(parts)
        start = time.process_time()
        vetted = vet_document(source, "yaml", variants=3)
        seconds = time.process_time() - start
        if vetted.document is None:
            errors = "; ".join(f"{where}: {message}" for where, message in vetted.errors)
            print(f"FAIL {path.stem} ({seconds:.1f}s): {errors[:1200]}")
            continue
        derived = derive_doc(vetted.document, symbol_table(vetted.document))
        for part in parts:
            quantity = part.get("quantity", part["id"])
            methods = derived.agreement.get(quantity, ())
            sim = simulated(derived.raw, quantity)
            ok = len(methods) >= 2 and sim
            good += ok
            print(
                f"{'ok  ' if ok else 'WEAK'} {path.stem}.{quantity} = {derived.quantities.get(quantity)}"
                f"  methods={list(methods)} sim={sim} ({seconds:.1f}s)"
            )
    print(f"derived by >=2 methods with simulation: {good}/{total}")


if __name__ == "__main__":
    main()
