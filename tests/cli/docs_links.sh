#!/usr/bin/env bash
# Every relative Markdown link in README.md and docs/ (and the validation READMEs) resolves (issue 40): the file or
# directory exists, and a #anchor names a heading of the target file (GitHub's rule: lower case, punctuation
# but hyphens and underscores dropped, spaces to hyphens, -1, -2 ... for repeats). Links inside code are not links.
# Usage: bash docs_links.sh <bin dir (unused)> <source dir>. Needs python3 only: no build.
set -uo pipefail
src="$2"
python3 - "$src" <<'PY'
import pathlib, re, sys
src = pathlib.Path(sys.argv[1])
files = [src / "README.md"] + sorted((src / "docs").rglob("*.md")) + sorted((src / "validation").glob("*/README.md"))

def drop_fences(text):
    """The text without its fenced code blocks (CommonMark: a fence of 3+ backticks or tildes, closed by one at
    least as long; a backtick fence's info string has no backtick)."""
    out, fence = [], None
    for line in text.split("\n"):
        m = re.match(r"^ {0,3}(`{3,}|~{3,})(.*)$", line)
        if fence is None:
            if m and not (m.group(1)[0] == "`" and "`" in m.group(2)):
                fence = m.group(1)
                continue
            out.append(line)
        elif m and m.group(1)[0] == fence[0] and len(m.group(1)) >= len(fence) and not m.group(2).strip():
            fence = None
    return "\n".join(out)


def strip_code(text):
    return re.sub(r"(`+)[^`].*?\1", "", drop_fences(text), flags=re.S)

def anchors(path, cache={}):
    if path not in cache:
        seen, out = {}, set()
        body = drop_fences(path.read_text())
        for m in re.finditer(r"^#{1,6}\s+(.*?)\s*#*\s*$", body, re.M):
            a = re.sub(r"[^\w\- ]", "", m.group(1).strip().lower()).replace(" ", "-")
            n = seen.get(a, 0)
            seen[a] = n + 1
            out.add(a if n == 0 else f"{a}-{n}")
        cache[path] = out
    return cache[path]

failures, count = 0, 0
for f in files:
    text = strip_code(f.read_text())
    for m in re.finditer(r"!?\[[^\]]*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)", text):
        target = m.group(1)
        if re.match(r"[a-z][a-z0-9+.-]*:", target, re.I):
            continue  # http:, https:, mailto:
        count += 1
        path, _, anchor = target.partition("#")
        dest = (f.parent / path).resolve() if path else f
        where = f"{f.relative_to(src)}: ({target})"
        if not dest.exists():
            print(f"FAIL: {where}: {path} does not exist"); failures += 1; continue
        if anchor and dest.suffix == ".md" and anchor not in anchors(dest):
            print(f"FAIL: {where}: no heading of {dest.relative_to(src)} has the anchor #{anchor}"); failures += 1
print(f"{count} relative links in {len(files)} files checked, {failures} broken")
sys.exit(1 if failures else 0)
PY
