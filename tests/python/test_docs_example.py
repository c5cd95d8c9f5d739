"""The worked example of docs/python.md runs as written and draws its figure (needs matplotlib: Debian's
python3-matplotlib; without it the test is skipped with that reason)."""
import os
import re

import pytest

from doc_blocks import SOURCE, one_block


def example_code():
    return one_block("python.md", "example")


def test_worked_example_draws_the_parity_plot(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib", reason="matplotlib is not installed (Debian: python3-matplotlib)")
    code = example_code()
    for name in re.findall(r'"((?:validation|data)/[^"]+)"', code):
        code = code.replace(f'"{name}"', repr(str(SOURCE / name)))
    monkeypatch.chdir(tmp_path)
    exec(compile(code, "docs/python.md", "exec"), {})
    png = tmp_path / "k9_parity_axial_force.png"
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert (tmp_path / "k9_parity_axial_force.pdf").read_bytes()[:5] == b"%PDF-"
    if os.environ.get("KERF_UPDATE_DOCS_IMG") == "1":
        (SOURCE / "docs" / "img" / "python_k9_parity_axial_force.png").write_bytes(png.read_bytes())
