"""The repository's scripts (validation/<case>/, analysis/) as modules for their tests, loaded from their files:
nothing is put on sys.path (tests/python/test_no_path_insertion.py). The scripts import kerf's own statistics and
readers (kerf.stats, kerf.records) from the module under test, like any user of it."""
import importlib.util
import pathlib
import sys

ROOT = pathlib.Path(__file__).resolve().parents[2]


def load(relative):
    """The script at ROOT/`relative` as a module (named script_<its stem>, registered in sys.modules)."""
    path = ROOT / relative
    name = f"script_{path.stem}"
    spec = importlib.util.spec_from_file_location(name, path)
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    spec.loader.exec_module(module)
    return module
