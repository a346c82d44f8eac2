"""Shared by the package's tests: the command-line binary, run as a user runs it, for comparisons."""
import json
import os
import pathlib
import subprocess

import pytest

REPOSITORY = pathlib.Path(__file__).resolve().parents[2]
DATA = pathlib.Path(os.environ.get("SUPERPACK_TEST_DATA", REPOSITORY / "tests" / "data"))
BINARY = os.environ.get("SUPERPACK_BINARY", str(REPOSITORY / "build" / "superpack"))


def run_cli(*arguments):
    """(exit code, the JSON document) of `superpack ARGUMENTS --json`."""
    finished = subprocess.run([BINARY, *arguments, "--json"], capture_output=True, text=True, check=False)
    return finished.returncode, json.loads(finished.stdout)


def without_timings(value):
    """A document without its wall-clock times (keys ending in "seconds"), which differ run to run."""
    if isinstance(value, dict):
        return {key: without_timings(entry) for key, entry in value.items() if not key.endswith("seconds")}
    if isinstance(value, list):
        return [without_timings(entry) for entry in value]
    return value


@pytest.fixture
def golden():
    """mpmath's values at 50 digits (tests/data/golden.json, from scripts/make_golden.py)."""
    with open(DATA / "golden.json") as file:
        return json.load(file)
