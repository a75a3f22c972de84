"""Shared by the tests of the Python module: the repository, the command line
built beside the module, and the shipped designs (as the ctest "designs:" tests
list them)."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


def cli_path():
    path = os.environ.get("SWEETSPOT_CLI")
    return path if path else str(ROOT / "build" / "sweetspot")


def run_cli(*args, check=True):
    """The command line's standard output, standard error and status."""
    done = subprocess.run([cli_path(), *map(str, args)], capture_output=True, text=True, cwd=ROOT)
    if check and done.returncode != 0:
        raise AssertionError(f"sweetspot {' '.join(map(str, args))}: {done.stderr}")
    return done


def cli_json(*args):
    return json.loads(run_cli(*args).stdout)


def shipped_designs():
    """Every shipped design file: designs/ without the studies and the column maps."""
    found = []
    for path in sorted((ROOT / "designs").rglob("*.json")):
        relative = path.relative_to(ROOT).as_posix()
        if relative.startswith("designs/studies/") or (
            relative.startswith("designs/catalogues/") and relative.endswith("-map.json")
        ):
            continue
        found.append(relative)
    return found


@pytest.fixture(scope="session")
def root():
    return ROOT
