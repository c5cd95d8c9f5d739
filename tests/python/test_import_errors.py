"""When kerf cannot be imported, one line says why and names the interpreter to use (issue 55): numpy missing, or
an interpreter of another version than the one the module was built for (python/kerf_fallback.py.in)."""
import os
import pathlib
import shutil
import subprocess
import sys

import pytest

import kerf

MODULE = pathlib.Path(kerf.__file__)


def last_line(result):
    lines = result.stderr.strip().splitlines()
    return lines[-1] if lines else ""


def test_numpy_missing_says_so(tmp_path):
    shutil.copy2(MODULE, tmp_path / MODULE.name)
    # python -S: no site directories, so no numpy from them; kerf from tmp_path alone.
    env = dict(os.environ, PYTHONPATH=str(tmp_path))  # -S leaves PYTHONPATH in force
    probe = subprocess.run([sys.executable, "-S", "-c", "import numpy"], capture_output=True, text=True, env=env)
    if probe.returncode == 0:
        pytest.skip("numpy is importable without site directories here")
    result = subprocess.run([sys.executable, "-S", "-c", "import kerf"], capture_output=True, text=True, env=env)
    assert result.returncode != 0
    line = last_line(result)
    assert line.startswith(f"ImportError: kerf needs numpy, which {sys.executable} (Python "), result.stderr
    assert "python3-numpy" in line
    assert "initialization failed" not in result.stderr


def test_other_interpreter_names_the_one_to_use(tmp_path):
    # The compiled module as another interpreter would see it: a file whose suffix is not this Python's.
    shutil.copy2(MODULE, tmp_path / "kerf.cpython-39-x86_64-linux-gnu.so")
    shutil.copy2(MODULE.parent / "kerf.py", tmp_path / "kerf.py")
    result = subprocess.run([sys.executable, "-c", "import kerf"], capture_output=True, text=True,
                            env={"PYTHONPATH": str(tmp_path), "PATH": "/usr/bin:/bin"})
    assert result.returncode != 0
    line = last_line(result)
    assert line.startswith("ImportError: kerf was built for "), result.stderr
    assert "kerf.cpython-39-x86_64-linux-gnu.so" in line and f"not for {sys.executable}" in line
    assert "run " in line


def test_stand_in_beside_the_module():
    assert (MODULE.parent / "kerf.py").is_file()
