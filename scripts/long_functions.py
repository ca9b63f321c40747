#!/usr/bin/env python3
"""Lists the C++ functions longer than a threshold (issue 42, item 7).

Usage: scripts/long_functions.py [FOLDER ...] [THRESHOLD]
       (default: source and include under the repository root, 80 lines)

Prints one line per function whose length exceeds THRESHOLD, longest
first: "lines  file:line  name", then how many are over THRESHOLD and how
many over 120 lines.

A function's length counts the lines from the one holding its name (the
declarator: 'Parameters::parse(' under a 'void' line counts from the name's
line, as deal.II style puts it) to the line of its closing brace, both
included.

The heuristics (a scanner, not a C++ parser; good enough for this code base):
- Comments, string and character literals (raw strings included) and
  preprocessor lines are blanked out first, keeping the line structure.
- Outside any function body, the text since the last ';', '{' or '}' is the
  "header" of the next '{'. The brace opens a function body when the header
  has a top-level '(' and, after its last top-level ')', only qualifiers
  (const, override, final, noexcept, mutable, '&', a trailing return type
  '-> T') or a constructor's initializer list (': a(x), b{y}'). Braces of a
  brace-initialised member in that list ('b{y}') are recognised because the
  header then ends in the list, and they do not end the header.
- Headers starting with namespace, class, struct, union, enum, extern or
  holding '=' outside parentheses (a variable's initializer) open no
  function; their braces are descended into, so member functions defined in
  a class body (the inline ones of a header) and functions in namespaces are
  found.
- Inside a function body nothing is looked for: lambdas and local classes
  count towards the enclosing function.
- The name is the identifier (with its qualification, e.g. 'Foo<dim>::bar')
  before the header's first top-level '('; a lambda at namespace scope is
  listed as '<lambda>'.
"""
import functools
import os
import re
import sys

EXTENSIONS = ('.cc', '.h', '.cpp', '.hpp')
QUALIFIERS = re.compile(
    r'^(\s*(const|override|final|noexcept(\s*\([^)]*\))?|mutable|&&?|'
    r'->\s*[\w:<>,\s*&]+?))*\s*$')
NON_FUNCTION = re.compile(r'^\s*(template\s*<[^{;]*>\s*)?'
                          r'(namespace|class|struct|union|enum|extern)\b')


@functools.lru_cache(maxsize=None)
def blank_out(text):
    """Comments, literals and preprocessor lines replaced by spaces (newlines
    kept, so that offsets and line numbers stay)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c in ' \t':
            out.append(c)
            i += 1
            continue
        if line_start and c == '#':
            # A preprocessor line, with its continuations.
            while i < n and text[i] != '\n':
                if text[i] == '\\' and i + 1 < n and text[i + 1] == '\n':
                    out.append(' \n')
                    i += 2
                    continue
                out.append(' ')
                i += 1
            continue
        line_start = False
        if text.startswith('//', i):
            while i < n and text[i] != '\n':
                out.append(' ')
                i += 1
            continue
        if text.startswith('/*', i):
            end = text.find('*/', i + 2)
            end = n if end < 0 else end + 2
            out.append(re.sub(r'[^\n]', ' ', text[i:end]))
            i = end
            continue
        raw = re.match(r'(u8|u|U|L)?R"([^(\s]*)\(', text[i:i + 40])
        if raw and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == '_')):
            end = text.find(')' + raw.group(2) + '"', i + raw.end())
            end = n if end < 0 else end + len(raw.group(2)) + 2
            out.append('""' + re.sub(r'[^\n]', ' ', text[i + 2:end]))
            i = end
            continue
        if c in '"\'':
            # A digit separator (1'000) is no character literal.
            if c == "'" and i > 0 and text[i - 1].isalnum() and \
                    i + 1 < n and text[i + 1].isalnum() and \
                    re.match(r'[0-9a-fA-FxX]', text[i - 1]):
                out.append(' ')
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != '\n':
                j += 2 if text[j] == '\\' else 1
            j = min(j + 1, n)
            out.append(c + ' ' * (j - i - 2) + c if j - i >= 2 else c)
            i = j
            continue
        if c == '\n':
            line_start = True
        out.append(c)
        i += 1
    return ''.join(out)


def top_level(header):
    """The header with everything inside (), <> of templates left as is but
    the parts inside parentheses replaced by spaces; returns (text, positions
    of the top-level '(' and ')')."""
    depth = 0
    opens, closes = [], []
    chars = []
    for k, c in enumerate(header):
        if c == '(':
            if depth == 0:
                opens.append(k)
            depth += 1
            chars.append(c)
            continue
        if c == ')':
            depth = max(depth - 1, 0)
            if depth == 0:
                closes.append(k)
            chars.append(c)
            continue
        chars.append(' ' if depth > 0 else c)
    return ''.join(chars), opens, closes


def last_name(text):
    """The last name in @p text, template arguments and qualification
    included ('Foo<dim>::bar', 'operator()')."""
    operator = re.search(r'operator\s*(\S+)\s*$', text)
    if operator:
        text = text[:operator.start()].rstrip()
        return last_name(text + ' ' + 'operator') + operator.group(1) \
            if text.endswith('::') else 'operator' + operator.group(1)
    depth = 0
    k = len(text)
    while k > 0:
        c = text[k - 1]
        if c == '>':
            depth += 1
        elif c == '<':
            depth -= 1
        elif depth == 0 and c.isspace() and not text[:k].rstrip().endswith('::') \
                and not text[k:].lstrip().startswith('::'):
            break
        k -= 1
    return re.sub(r'\s+', '', text[k:])


def classify(header):
    """'function' with its name, 'init' (a brace-initialised member of a
    constructor's initializer list), or None (any other block)."""
    if NON_FUNCTION.match(header):
        return None, None
    flat, opens, closes = top_level(header)
    if not opens:
        # 'Foo() : member{' : the brace of a member in the initializer list.
        return None, None
    if '=' in flat.replace('==', '').replace('<=', '').replace('>=', '') \
            .replace('!=', '').replace('operator=', ''):
        if not re.search(r'operator\s*[^\s(]*=', flat):
            return None, None
    after = header[closes[-1] + 1:] if closes else ''
    before = flat[:opens[0]].rstrip()
    name = last_name(before)
    if before.endswith(']') or not before:
        name = '<lambda>'
    if QUALIFIERS.match(after):
        return 'function', name
    # A constructor's initializer list: ') : a(x), b(y)' or ', c'.
    init = re.match(r'^\s*(noexcept\s*)?:\s*[^;]*$', after)
    if init:
        tail = after.rstrip()
        if tail.endswith(')') or tail.endswith('}'):
            return 'function', name
        return 'init', name
    return None, None


def functions(path):
    """(name, first line, last line) of every function body in @p path."""
    with open(path, encoding='utf-8', errors='replace') as f:
        text = blank_out(f.read())
    found = []
    header_start = 0
    stack = []  # 'function', 'block' or 'init'
    function_depth = None
    function_name, function_line = None, 0
    i = 0
    for i, c in enumerate(text):
        if c == '{':
            if function_depth is None:
                header = text[header_start:i]
                kind, name = classify(header)
                if kind == 'function':
                    flat, opens, _ = top_level(header)
                    name_at = header_start + (opens[0] if opens else 0)
                    function_line = text.count('\n', 0, name_at) + 1
                    function_name = name
                    function_depth = len(stack)
                    stack.append('function')
                elif kind == 'init':
                    stack.append('init')
                    continue  # the header goes on after the member's braces
                else:
                    stack.append('block')
            else:
                stack.append('block')
            header_start = i + 1
        elif c == '}':
            kind = stack.pop() if stack else 'block'
            if kind == 'init':
                continue
            if kind == 'function' and function_depth == len(stack):
                last = text.count('\n', 0, i) + 1
                found.append((function_name, function_line, last))
                function_depth = None
            header_start = i + 1
        elif c == ';' and function_depth is None:
            header_start = i + 1
    return found


def main(argv):
    threshold = 80
    folders = []
    for arg in argv:
        if arg.isdigit():
            threshold = int(arg)
        else:
            folders.append(arg)
    if not folders:
        root = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
        folders = [os.path.join(root, 'source'), os.path.join(root, 'include')]
    rows = []
    for folder in folders:
        paths = [folder] if os.path.isfile(folder) else [
            os.path.join(d, f) for d, _, files in os.walk(folder)
            for f in files if f.endswith(EXTENSIONS)]
        for path in sorted(paths):
            for name, first, last in functions(path):
                length = last - first + 1
                if length > threshold:
                    rows.append((length, path, first, name))
    rows.sort(key=lambda r: (-r[0], r[1], r[2]))
    for length, path, first, name in rows:
        print(f'{length:5d}  {path}:{first}  {name}')
    print(f'{len(rows)} functions over {threshold} lines, '
          f'{sum(1 for r in rows if r[0] > 120)} over 120')


if __name__ == '__main__':
    main(sys.argv[1:])
