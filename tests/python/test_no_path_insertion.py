"""No script reaches another by editing Python's module path (issue 56): shared code lives in the module kerf
(kerf.stats, kerf.records), scripts and tests import it from there, and the tests load the scripts they test from
their files (tests/python/repo_scripts.py)."""
import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
SKIP = {".git", "build", "out", "__pycache__"}
# sys.path.insert / .append / .extend / [...] = / += / = [...], and site.addsitedir (this file aside).
EDIT = re.compile(r"\bsys\s*\.\s*path\s*(\.\s*(insert|append|extend)\s*\(|\[[^\]]*\]\s*=|\+=|=(?!=))|"
                  r"\bsite\s*\.\s*addsitedir\s*\(")


def sources():
    """The Python, notebook and shell files of the source tree (build folders, out/ and .git aside)."""
    for path in ROOT.rglob("*"):
        folders = path.relative_to(ROOT).parts[:-1]
        if path.suffix in (".py", ".ipynb", ".sh") and path != pathlib.Path(__file__).resolve() and \
                not SKIP & set(folders) and not (folders and folders[0].startswith("build")):
            yield path


def test_no_source_edits_the_module_path():
    found = [f"{p.relative_to(ROOT)}:{n}: {line.strip()}" for p in sources()
             for n, line in enumerate(p.read_text(errors="replace").splitlines(), 1) if EDIT.search(line)]
    assert not found, "sys.path edited (import kerf's submodules, or load a script from its file):\n" + "\n".join(found)


def test_the_check_sees_an_insertion():
    assert EDIT.search('sys.path.insert(0, str(pathlib.Path(__file__).parent))')
    assert EDIT.search("sys.path += ['bench']") and EDIT.search("sys.path[:0] = ['bench']")
    assert EDIT.search("site.addsitedir('bench')")
    assert not EDIT.search("if sys.path == []:") and not EDIT.search("print(sys.path)")
