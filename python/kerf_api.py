# The Python half of the module `kerf` (python/CMakeLists.txt compiles this file into the module as text; it runs
# in the module's namespace at import): the public functions with Python signatures and docstrings over the C++
# functions (_predict, _sweep, ...), the bundled scenes, and the reader of a DEM run's VTK frames.
import os as _os
import pathlib as _pathlib
import re as _re
import xml.etree.ElementTree as _ElementTree

import numpy as _numpy

InputError.__doc__ = (
    "Bad input (a ValueError): the one line the programs print, with .field (the dotted key or option), .value "
    "(what was given) and .expected (what is valid).")
ModelError.__doc__ = "A model that failed on input it accepted (a RuntimeError): which model and why."


def predict(scene, /, **overrides):
    """One prediction: the columns of `kerf-forces predict --csv` as a dict.

    scene: a path (str or os.PathLike) or a dict holding the scene. overrides: `--set` as keyword arguments, a
    dotted key (**{"tool.edge_radius_um": 0.2}) or "__" for each dot (tool__edge_radius_um=0.2).

    Numbers are floats, text is str, an absent value is None; 'guards' and 'warnings' are lists of str (empty
    when none fired). Raises InputError for bad input, ModelError when a model fails.

    >>> kerf.predict("data/scenes/psic_liu_li.json", tool__edge_radius_um=0.2)["cutting_force_N"]
    """
    return _predict(scene, **overrides)


def sweep(scene, /, *, vary, frame=False, **overrides):
    """The cartesian product of the varied keys, one row per point.

    vary: {key: values} (values a sequence). Returns a dict of numpy arrays, one per column: the varied keys,
    the prediction's columns (float64 where numeric, NaN at a refused point; object arrays of str or None for
    text; 'guards' and 'warnings' lists of str), and 'error' (None where the point was predicted, the message
    where the models refused it). frame=True returns a pandas DataFrame of the same columns (ImportError when
    pandas is not installed). A key the scene does not read raises InputError. The points run in parallel
    (OpenMP's threads), through the same library sweep as kerf-forces sweep.
    """
    columns = _sweep(scene, vary, **overrides)
    if not frame:
        return columns
    try:
        import pandas
    except ImportError:
        raise ImportError("kerf.sweep(..., frame=True) needs pandas, which is not installed (pip install pandas, "
                          "or apt install python3-pandas); frame=False returns the columns as a dict of numpy "
                          "arrays") from None
    return pandas.DataFrame(columns)


def compare(scene, experiments, /, *, map=None, fit=False, pool=False, measured_width_mm=None, out=None,
            **overrides):
    """Holds a scene against measured forces (kerf-forces compare).

    experiments: a CSV file; map: {scene_key_or_prediction_column: csv_column}. Returns a dict: 'quantities'
    (per quantity the error metrics and the measured and predicted means as arrays), 'notes', 'unused_columns',
    'rows' (per CSV row its regime, and 'guards' and 'warnings' lists); with out (a directory) the report
    (report.md, CSV, JSON, plots) is written there and 'files' lists it. A CSV none of whose columns sets a
    condition raises InputError unless pool=True (every row a measurement at the scene's own condition).
    fit=True first fits the trepanning model's lumped groups to the measured rows (kerf-forces compare --fit);
    measured_width_mm: the width the measured forces act over (--measured-width-mm).
    """
    return _compare(scene, experiments, {} if map is None else map, fit, pool, measured_width_mm, out,
                    **overrides)


def materials():
    """The bundled material library: a list of dicts with 'name', 'title', 'groups' and 'file'."""
    return _materials()


def models():
    """Every registered analytic model: a list of dicts with 'kind', 'name', 'summary' and 'needs'."""
    return _models()


def scenes():
    """The bundled example scenes (data/scenes, or $KERF_DATA_DIR/scenes): a list of dicts with 'name' (what
    scene_path takes), 'path', 'program' ('kerf-forces' or 'kerf-dem'), 'kind' (the kerf-dem kind; None for a
    kerf-forces scene) and 'description'."""
    return _scenes()


def scene_path(name):
    """The path (pathlib.Path) of a bundled scene by its name ('dem_cut' or 'dem_cut.json'); InputError with the
    nearest name for an unknown one. kerf.predict(kerf.scene_path("psic_liu_li"))."""
    return _pathlib.Path(_scene_path(str(name)))


def _run(scene, /, *, out, threads=None, replicates=1, checkpoint_every=0, progress=None, **overrides):
    """Runs a kerf-dem scene into the directory `out` (kerf-dem run).

    Returns a dict: 'exit_status', 'summary' (summary.json as a dict), 'out', and 'forces', 'cracks', 'curve':
    the CSV files of the run as dicts of numpy arrays, None for a table the kind does not write (a cut writes no
    curve, a lab test no forces). threads sets OpenMP's threads for the run (restored after it); replicates
    runs that many packings (kerf-dem run --replicates); checkpoint_every writes a checkpoint every that many
    samples (0: none).
    progress(stage, done, total, unit), if given, is called as the run advances: stage a str ('specimen
    genesis', 'cut', ...), done and total ints in unit ('steps' or 'particle-steps'); every stage ends at
    done == total. An exception it raises stops the run and reaches the caller.
    """
    return _dem_run(scene, out, threads, replicates, checkpoint_every, progress, **overrides)


def _kinds():
    """The kerf-dem scene kinds: a list of str."""
    return _dem_kinds()


_VTK_TYPES = {"Float64": "<f8", "Float32": "<f4", "Int64": "<i8", "Int32": "<i4", "UInt8": "u1", "UInt64": "<u8"}


def _read_vtp(path):
    """One VTK XML PolyData file as written by kerf-dem (appended raw data, UInt64 headers): a dict of numpy arrays."""
    data = _pathlib.Path(path).read_bytes()
    start = data.find(b"<AppendedData")
    if start < 0:
        raise InputError(str(path), "(no AppendedData)", "a .vtp file written by kerf-dem (appended raw data)")
    underscore = data.index(b"_", data.index(b">", start)) + 1
    head = data[:start].decode("utf-8") + "</VTKFile>"
    root = _ElementTree.fromstring(head)
    little = root.get("byte_order", "LittleEndian") == "LittleEndian"
    if root.get("header_type", "UInt32") != "UInt64":
        raise InputError(str(path), root.get("header_type", "UInt32"), "header_type UInt64 (kerf-dem's frames)")
    piece = root.find("PolyData/Piece")
    out = {"n_points": int(piece.get("NumberOfPoints")), "n_verts": int(piece.get("NumberOfVerts", "0")),
           "n_lines": int(piece.get("NumberOfLines", "0"))}

    def array(element):
        dtype = _numpy.dtype(_VTK_TYPES[element.get("type")])
        dtype = dtype.newbyteorder("<" if little else ">") if dtype.itemsize > 1 else dtype
        offset = underscore + int(element.get("offset"))
        size = int(_numpy.frombuffer(data, dtype="<u8" if little else ">u8", count=1, offset=offset)[0])
        values = _numpy.frombuffer(data, dtype=dtype, count=size // dtype.itemsize, offset=offset + 8).copy()
        components = int(element.get("NumberOfComponents", "1"))
        return values.reshape(-1, components) if components > 1 else values

    for section in piece:
        arrays = {a.get("Name"): array(a) for a in section.findall("DataArray")}
        if section.tag == "Points":
            out.update(arrays)  # position_mm
        elif section.tag == "PointData":
            out.update(arrays)
        elif section.tag == "CellData":
            # The cells are the vertices (one per point, placeholders) and then the lines: one value per line.
            out.update({name: values[out["n_verts"]:] for name, values in arrays.items()})
        elif section.tag == "Lines" and out["n_lines"]:
            out["lines"] = arrays["connectivity"].reshape(-1, 2)
    return out


def _read_frames(directory, steps=None):
    """The VTK frames of a kerf-dem run: its .pvd series (result.pvd) read into numpy arrays, no VTK needed.

    directory: the run's output directory (or one .pvd file).
    steps: the indices of the time steps to read, in time order (frame_K.vtp is step K); None (the default): all.

    Returns a list, one dict per time step read, in time order: 'time_s' (float) and, per part the run wrote,
    'particles', 'walls', 'cracks' (each a dict of numpy arrays named as in the files: 'position_mm' (n, 3),
    the point arrays ('radius_mm', 'velocity_m_per_s', ...), 'lines' (m, 2) point indices of the joints or
    walls, and the line arrays ('intact_elements', 'bond', 'force_N', ...) one value per line; 'n_points').
    With VTK installed, vtk.vtkXMLPolyDataReader reads the same files.
    """
    directory = _pathlib.Path(directory)
    series = sorted(directory.glob("*.pvd")) if directory.is_dir() else [directory]
    if not series or not series[0].is_file():
        raise InputError("directory", str(directory), "a kerf-dem output directory with a .pvd series "
                         "(output.frame_every_samples > 0 writes one)")
    files = {}
    for pvd in series:
        for dataset in _ElementTree.parse(pvd).getroot().iter("DataSet"):
            name = dataset.get("name") or _re.sub(r"_.*", "", dataset.get("file"))
            files.setdefault(float(dataset.get("timestep")), {})[name] = pvd.parent / dataset.get("file")
    times = sorted(files)
    if steps is not None:
        wanted = list(steps)
        bad = [k for k in wanted if not 0 <= k < len(times)]
        if bad:
            raise InputError("steps", str(bad[0]), f"indices of the run's {len(times)} time steps (0 to {len(times) - 1})")
        times = [times[k] for k in wanted]
    return [{"time_s": t, **{name: _read_vtp(path) for name, path in files[t].items()}} for t in times]


_run.__name__ = _run.__qualname__ = "run"
_run.__module__ = "kerf.dem"
_kinds.__name__ = _kinds.__qualname__ = "kinds"
_kinds.__module__ = "kerf.dem"
_read_frames.__name__ = _read_frames.__qualname__ = "read_frames"
_read_frames.__module__ = "kerf.dem"
dem.run, dem.kinds, dem.read_frames = _run, _kinds, _read_frames
del _run, _kinds, _read_frames


def __getattr__(name):
    """The compiled module is also a package: its pure-Python submodules (kerf.stats, kerf.records: python/kerf/)
    lie in the folder kerf/ beside it, where python/CMakeLists.txt copies them. Python asks for __path__ when it
    imports a submodule, once the import has given the module its __file__ (it has none while this file runs)."""
    if name == "__path__":
        return [_os.path.join(_os.path.dirname(__file__), "kerf")]
    raise AttributeError(f"module 'kerf' has no attribute '{name}'")
