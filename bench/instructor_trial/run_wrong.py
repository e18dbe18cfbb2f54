"""Each wrong model must be refused, with a message naming its real cause. Prints REFUSED/VERIFIED."""

import pathlib
import sys

from problems.vetting import vet_document

for path in sorted(pathlib.Path(sys.argv[1]).glob("*.yaml")):
    if len(sys.argv) > 2 and sys.argv[2] not in path.stem:
        continue
    vetted = vet_document(path.read_text(), "yaml", variants=3)
    if vetted.document is None:
        errors = "; ".join(f"{where}: {message}" for where, message in vetted.errors)
        print(f"REFUSED  {path.stem}: {errors[:600]}")
    else:
        print(f"VERIFIED {path.stem}")
