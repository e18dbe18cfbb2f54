# The two commands of the README: `make serve` and `make test`. Both set up .venv from the lock first.
PYTHON ?= python3
VENV := .venv
BIN := $(VENV)/bin

.PHONY: serve test lint lock bank

$(BIN)/physcheck: requirements-dev.lock pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/pip install --quiet --upgrade pip
	$(BIN)/pip install --quiet -r requirements-dev.lock
	$(BIN)/pip install --quiet --no-deps -e .
	touch $@

serve: $(BIN)/physcheck
	$(BIN)/physcheck serve

# The derived bank shipped with the program (app/data/bank.compiled): a first start loads it instead of
# deriving the bank. Build it before a package (`pip wheel .`) so that the package carries it.
bank: $(BIN)/physcheck
	$(BIN)/physcheck bank build

lint: $(BIN)/physcheck
	$(BIN)/ruff check .
	$(BIN)/ruff format --check app physics problems tests bench
	$(BIN)/mypy

# The bank's per-problem self-test is `physcheck bank verify` (20 variants); pytest's copy of it is left out
# here. It also writes the derived bank (--build, as `make bank` does, from the same derivations): the
# tests' servers then load it as a first start from the package does, instead of each deriving, module
# by module, every bank problem it uses (a quarter of the page and service tests' CPU). Tests run on
# every core; an idle worker takes tests from a busy one (worksteal), so a file of slow parametrized
# tests is shared out (a module fixture, such as a live server, may then be set up once per worker);
# --durations names the slowest tests of each run.
test: lint
	$(BIN)/physcheck bank verify --build
	$(BIN)/pytest -q -n auto --dist worksteal -m "not bank_selftest" --durations=25

# Re-pin both locks from pyproject.toml (needs the network to PyPI).
lock:
	rm -rf /tmp/physcheck-lock && $(PYTHON) -m venv /tmp/physcheck-lock
	/tmp/physcheck-lock/bin/pip install --quiet . && /tmp/physcheck-lock/bin/pip freeze --exclude physcheck > requirements.lock
	/tmp/physcheck-lock/bin/pip install --quiet '.[dev]' && /tmp/physcheck-lock/bin/pip freeze --exclude physcheck > requirements-dev.lock
