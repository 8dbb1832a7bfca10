"""Shared helpers: the repository root, the command line to compare with, its JSON."""

import json
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]
SCENES = ROOT / "scenes"
# The command line the package is compared with (built by `cargo test --release` in CI).
BIN = pathlib.Path(os.environ.get("STRESSFIELD_BIN", ROOT / "target" / "release" / "stressfield"))


def cli(*args, check=True):
    """Runs the command line from the repository root; returns the completed process."""
    if not BIN.exists():
        pytest.fail(f"{BIN} is missing: build it with `cargo build --release` (or set STRESSFIELD_BIN)")
    done = subprocess.run([str(BIN), *map(str, args)], cwd=ROOT, capture_output=True, text=True)
    if check and done.returncode != 0:
        pytest.fail(f"stressfield {' '.join(map(str, args))} failed: {done.stderr}")
    return done


def cli_json(*args):
    """The JSON object a command prints (parsed exactly: Python reads shortest-repr floats
    back to the same double)."""
    return json.loads(cli(*args).stdout)


def cli_error(*args):
    """The message the command line prints after `error: ` (it must fail)."""
    done = cli(*args, check=False)
    assert done.returncode != 0, f"stressfield {args} should fail"
    text = done.stderr.strip()
    assert text.startswith("error: "), text
    return text[len("error: "):]
