#!/usr/bin/env bash
# User-facing text names the papers by author and year (issue 55 item 5): the team's labels "seed 000" ... "seed 003"
# (also "seed-000", "Seed 002's") mean a paper to the team but a random packing seed to a user. Fails listing every
# file:line where a label is left in a string, a doc, a data file's description or '#' citation line, a docstring.
# Allowed: docs/references.md (the map from label to paper), docs/notes/ (the dated notebook, as measured), this
# script (its samples) and code comments (C/C++ // and /* */, Python, shell and CMake #). Three digits after "seed":
# a plain "seed 0" can be a packing's seed. Checks its own scanner first on samples that must and must not be flagged.
# Usage: bash seed_labels.sh <bin dir (unused)> <source dir>. Needs python3 only: no build.
set -uo pipefail
src="$2"
python3 - "$src" <<'PY'
import io, pathlib, re, subprocess, sys, tokenize

src = pathlib.Path(sys.argv[1])
LABEL = re.compile(r"\bseeds?[ -]0[0-9]{2}", re.I)
ALLOWED = ("docs/references.md", "docs/notes/", "tests/cli/seed_labels.sh")  # the last: its own samples
EXCLUDED = ()
C_LIKE = {".cpp", ".hpp", ".h", ".cc", ".c", ".cxx", ".hxx"}


def c_code(text):
    """The text with C/C++ comments blanked (newlines kept); string and character literals, raw strings too, kept."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i)); i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j])); i = j
        elif (m := re.match(r'R"([^(\s]*)\(', text[i:i + 20])) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            end = text.find(")" + m.group(1) + '"', i)
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(text[i:j]); i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            out.append(text[i:j + 1]); i = j + 1
        else:
            out.append(c); i += 1
    return "".join(out)


def python_code(text):
    """The text with Python comments blanked; docstrings and strings kept (they are user-facing)."""
    lines = text.split("\n")
    try:
        for tok in tokenize.generate_tokens(io.StringIO(text).readline):
            if tok.type == tokenize.COMMENT:
                (r, c0), (_, c1) = tok.start, tok.end
                lines[r - 1] = lines[r - 1][:c0] + " " * (c1 - c0) + lines[r - 1][c1:]
    except (tokenize.TokenError, SyntaxError, IndentationError):
        return hash_code(text)
    return "\n".join(lines)


def hash_code(text):
    """Shell or CMake: a '#' that starts a word outside quotes starts a comment (a line's quotes only)."""
    out = []
    for line in text.split("\n"):
        quote, cut = None, len(line)
        for k, ch in enumerate(line):
            if quote:
                if ch == quote: quote = None
            elif ch in "\"'":
                quote = ch
            elif ch == "#" and (k == 0 or line[k - 1] in " \t;(|&"):
                cut = k; break
        out.append(line[:cut])
    return "\n".join(out)


def code_of(path, text):
    suffix = pathlib.PurePath(path).suffix
    if suffix in C_LIKE: return c_code(text)
    if suffix == ".py": return python_code(text)
    if suffix in {".sh", ".cmake"} or pathlib.PurePath(path).name in {"CMakeLists.txt", ".clang-format"}:
        return hash_code(text)
    return text  # Markdown, JSON, CSV (its '#' lines are citations), CFF, TOML...: all user-facing


def hits(path, text):
    return [(k, line.strip()) for k, line in enumerate(code_of(path, text).split("\n"), 1) if LABEL.search(line)]


# The scanner itself: what must be flagged is, what is a comment or a packing seed is not.
samples = {
    ("a.cpp", 'x = "Seed 000, Table 2";  // seed 001 here is fine\n/* seed 002 */ y = R"(seed-003)";\n'): [1, 2],
    ("a.py", '"""Docstring, seed 000."""\nx = 1  # seed 001\ny = "seeds 002"\n'): [1, 3],
    ("a.sh", 'echo "seed 000" # seed 001\n# seed 002\nx="a#b seed 003"\n'): [1, 3],
    ("a.json", '{"description": "seed 000\'s Table 2, packing seed 0, seed 1"}\n'): [1],
    ("a.md", "Packing seed 0 and seeds 1-4; seed000_steady.json is a file name.\n"): [],
}
bad = [(p, [k for k, _ in hits(p, t)], want) for (p, t), want in samples.items() if [k for k, _ in hits(p, t)] != want]
if bad:
    for p, got, want in bad: print(f"FAIL: the scanner flags lines {got} of its sample {p}, expected {want}")
    sys.exit(1)

if (src / ".git").exists():
    files = subprocess.run(["git", "-C", str(src), "ls-files"], capture_output=True, text=True, check=True).stdout.split("\n")
else:
    files = [str(p.relative_to(src)) for p in src.rglob("*") if p.is_file() and "build" not in p.parts]
places, scanned = [], 0
for f in filter(None, files):
    if f.startswith(ALLOWED) or any(e.match(f) if hasattr(e, "match") else f.startswith(e) for e in EXCLUDED):
        continue
    p = src / f
    if not p.is_file(): continue
    data = p.read_bytes()
    if b"\0" in data: continue
    scanned += 1
    places += [f"{f}:{k}: {line[:140]}" for k, line in hits(f, data.decode("utf-8", "replace"))]
for place in places: print("FAIL: a seed label in user-facing text (name the paper by author and year):", place)
if places:
    print(f"{len(places)} places; docs/references.md maps the labels to the papers")
    sys.exit(1)
print(f"no seed label in user-facing text ({scanned} files)")
PY
