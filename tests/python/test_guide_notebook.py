"""The notebook cell of docs/guide.md (task 7) runs as written, from a directory laid out as the repository root,
and draws its figure (needs matplotlib: Debian's python3-matplotlib; without it the test is skipped with that
reason)."""
import pytest

from doc_blocks import SOURCE, one_block


def notebook_code():
    return one_block("guide.md", "guide")


def test_guide_notebook_cell_runs_and_draws(tmp_path, monkeypatch):
    pytest.importorskip("matplotlib", reason="matplotlib is not installed (Debian: python3-matplotlib)")
    (tmp_path / "data").symlink_to(SOURCE / "data")
    (tmp_path / "out" / "guide").mkdir(parents=True)
    monkeypatch.chdir(tmp_path)
    namespace = {}
    exec(compile(notebook_code(), "docs/guide.md", "exec"), namespace)
    assert namespace["results"]["steady"] is False  # the guide's short cut is the entry's, and says so
    assert (tmp_path / "out" / "guide" / "notebook.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
