#!/usr/bin/env python3
"""Functions longer than a limit (default 80 lines, signature to closing brace) in C++ files, one per line:
length, file:line, name, and "reason" where a comment just above the function gives why it is long ("Long (...)
for a reason: ..."; issue 39: no function over ~80 lines without one).
Usage: python3 scripts/long-functions.py [--limit N] PATH... (files or folders).
A function is a brace block at namespace or class level whose head (the text since the previous ';', '{' or '}')
has a parameter list and is no class, struct, enum, namespace, initialiser or lambda."""
import pathlib, re, sys

def blank_strings_and_comments(text):
    """The text with comments, string and character literals replaced by spaces (newlines kept)."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:j])); i = j
        elif c == 'R' and text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) + len(m.group(1)) + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:end])); i = end
        elif c in '"\'' and not (c == "'" and i > 0 and text[i - 1].isalnum()):  # 1'000 digit separators
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (j + 1 - i)); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

def functions(path):
    text = blank_strings_and_comments(path.read_text())
    stack, head_start, found = [], 0, []  # stack: (kind, start offset)
    for i, c in enumerate(text):
        if c == '{':
            head = text[head_start:i]
            inside_function = any(k == 'f' for k, _ in stack)
            h = ' '.join(head.split())
            is_function = (not inside_function and '(' in h
                           and not re.search(r'\b(class|struct|enum|union|namespace)\b[^(]*$', h)
                           and not re.search(r'(=|\]\s*(\([^)]*\))?\s*(mutable)?\s*(->[^{]*)?)\s*$', h)
                           and not re.match(r'^(if|for|while|switch|do|else|try|catch)\b', h))
            if is_function:
                # the head's first line: skip leading blank lines
                s = head_start + len(head) - len(head.lstrip())
                stack.append(('f', s))
            else:
                stack.append(('b', i))
            head_start = i + 1
        elif c == '}':
            if stack:
                kind, s = stack.pop()
                if kind == 'f':
                    first = text.count('\n', 0, s) + 1
                    last = text.count('\n', 0, i) + 1
                    sig = ' '.join(text[s:text.index('(', s)].split())
                    name = sig.split()[-1] if sig.split() else '?'
                    found.append((last - first + 1, first, name))
            head_start = i + 1
        elif c == ';':
            head_start = i + 1
    return found

def main(argv):
    limit = 80
    if argv[:1] == ['--limit']:
        limit, argv = int(argv[1]), argv[2:]
    paths = []
    for a in argv:
        p = pathlib.Path(a)
        paths += sorted(q for q in p.rglob('*') if q.suffix in ('.cpp', '.hpp')) if p.is_dir() else [p]
    rows = []
    for p in paths:
        lines = p.read_text().split('\n')
        for n, line, name in functions(p):
            if n > limit:
                above = ' '.join(lines[max(0, line - 4):line - 1])
                rows.append((n, f'{p}:{line}', name, 'reason' if 'for a reason' in above else 'NO REASON'))
    for n, where, name, why in sorted(rows, key=lambda r: (-r[0], r[1])):
        print(f'{n:5d}  {where}  {name}  {why}')
    return 0

if __name__ == '__main__':
    sys.exit(main(sys.argv[1:]))
