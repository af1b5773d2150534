#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Lists the C++ functions longer than N lines (default 100), longest first.

    scripts/long-functions.py [-n N] [--fail] [PATH...]

PATHs are files or folders (default: vcg_core/src app/src cli, from the checkout's root). A
function's length runs from the line of its name to the line of its closing brace, both counted.
One line per function: LINES  FILE:LINE  NAME. --fail exits 1 when any function is listed.

A brace counter, not a compiler: comments, string and character literals (raw strings too) and
preprocessor lines are blanked first, then each '{' at namespace or class scope is classified by
the text before it (namespace, class/struct/enum, initializer, or a function: a parameter list's
')' with qualifiers after it, or a constructor's initializer list). Lambdas and local classes count
as part of the function that holds them.
"""
import argparse
import os
import re
import sys

SOURCE_SUFFIXES = (".cpp", ".cc", ".cxx", ".h", ".hpp")
DEFAULT_PATHS = ("vcg_core/src", "app/src", "cli")


def blank(text):
    """Returns text with comments, literals and preprocessor lines replaced by spaces (newlines kept)."""
    out = []
    i, n = 0, len(text)
    line_start = True
    while i < n:
        c = text[i]
        if line_start and c == "#":
            # A preprocessor line, with its backslash continuations.
            while i < n and text[i] != "\n":
                if text[i] == "\\" and i + 1 < n and text[i + 1] == "\n":
                    out.append(" \n")
                    i += 2
                    continue
                out.append(" ")
                i += 1
            continue
        if c == "\n":
            out.append(c)
            i += 1
            line_start = True
            continue
        if c in " \t":
            out.append(c)
            i += 1
            continue
        line_start = False
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            out.append(" " * (j - i))
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c == "R" and text.startswith('R"', i) and (i == 0 or not (text[i - 1].isalnum() or text[i - 1] == "_")):
            m = re.match(r'R"([^()\\ ]{0,16})\(', text[i:])
            if not m:
                out.append(c)
                i += 1
                continue
            end = text.find(")" + m.group(1) + '"', i + m.end())
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(re.sub(r"[^\n]", " ", text[i:j]))
            i = j
        elif c in "\"'":
            if c == "'" and i > 0 and text[i - 1].isalnum():
                # A digit separator (1'000'000), not a character literal.
                out.append(" ")
                i += 1
                continue
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            j = min(j + 1, n)
            out.append(" " * (j - i))
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def top_level(head):
    """The head with the inside of each top-level (...) blanked (same length, newlines kept)."""
    depth, kept = 0, []
    for ch in head:
        if ch == "(":
            kept.append("(" if depth == 0 else " ")
            depth += 1
        elif ch == ")":
            depth = max(depth - 1, 0)
            kept.append(")" if depth == 0 else " ")
        else:
            kept.append(ch if depth == 0 or ch == "\n" else " ")
    return "".join(kept)


QUALIFIERS = r"(?:\s*(?:const\b|noexcept\b|override\b|final\b|mutable\b|volatile\b|throw\b|&&|&|\(\s*\)))*"
FUNCTION_TAIL = re.compile(r"\)" + QUALIFIERS + r"\s*(?:->[^;{}=]*)?$")
CTOR_INIT = re.compile(r"\)" + QUALIFIERS + r"\s*:(?!:)")


def function_name(head):
    """The (qualified) name before the parameter list's '(' in a function head."""
    flat = top_level(head)
    for m in re.finditer(r"\(", flat):
        before = flat[: m.start()].rstrip()
        name = re.search(r"((?:[A-Za-z_~][\w]*\s*(?:<[^<>()]*>)?\s*::\s*)*(?:operator\s*[^\s\w(]+|operator\s+\w+|~?[A-Za-z_]\w*))$", before)
        if name and not re.fullmatch(r"decltype|alignas|__attribute__|sizeof", name.group(1)):
            return re.sub(r"\s+", "", name.group(1)), name.start(1)
    return None, None


def classify(head):
    """What a '{' at namespace or class scope opens, from the text since the previous ; { or }."""
    h = head.strip()
    flat = top_level(h)
    if re.search(r"\bnamespace\b", flat) or re.fullmatch(r"extern\s*", flat):
        return "scope"
    if "operator" not in flat:
        if re.search(r"=\s*$|=[^=]*$", flat) and "(" not in flat.split("=")[-1]:
            return "other"  # an initializer: int a[] = {
        if re.search(r"\b(class|struct|union)\b", flat) and not FUNCTION_TAIL.search(flat):
            return "scope"
        if re.search(r"\benum\b", flat):
            return "other"
    if FUNCTION_TAIL.search(flat):
        return "function"
    if CTOR_INIT.search(flat):
        # In a constructor's initializer list: a member's braces follow its name; the body follows
        # a member's closing ')' or '}'.
        return "function" if re.search(r"[)}]\s*$", flat) else "member-init"
    return "other"


def long_functions(path, limit):
    with open(path, encoding="utf-8", errors="replace") as f:
        text = blank(f.read())
    found = []
    stack = []  # kinds of the open braces: scope / other / member-init / function
    head_start = 0
    line = 1
    fn_start = None
    i = 0
    for i, ch in enumerate(text):
        if ch == "\n":
            line += 1
        elif ch == "{":
            if any(k == "function" for k in stack):
                stack.append("block")
                continue
            head = text[head_start:i]
            kind = classify(head) if not (stack and stack[-1] in ("other", "member-init")) else "other"
            stack.append(kind)
            if kind == "function":
                name, at = function_name(head)
                name_line = line - head[at:].count("\n") if name else line
                fn_start = (name or "?", name_line, line)
            elif kind == "scope":
                head_start = i + 1
        elif ch == "}":
            kind = stack.pop() if stack else "scope"
            if kind == "function" and fn_start:
                name, start, _ = fn_start
                if line - start + 1 > limit:
                    found.append((line - start + 1, path, start, name))
                fn_start = None
                head_start = i + 1
            elif kind == "scope":
                head_start = i + 1
        elif ch == ";" and not any(k in ("function", "other", "member-init") for k in stack):
            head_start = i + 1
    return found


def sources(paths):
    for p in paths:
        if os.path.isdir(p):
            for root, _, files in os.walk(p):
                for f in sorted(files):
                    if f.endswith(SOURCE_SUFFIXES):
                        yield os.path.join(root, f)
        elif os.path.isfile(p):
            yield p
        else:
            sys.exit(f"long-functions: no such file or folder: {p}")


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("-n", type=int, default=100, help="list functions longer than N lines (default 100)")
    parser.add_argument("--fail", action="store_true", help="exit 1 when any function is listed")
    parser.add_argument("paths", nargs="*", help="files or folders (default: " + " ".join(DEFAULT_PATHS) + ")")
    args = parser.parse_args()
    paths = args.paths
    if not paths:
        os.chdir(os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
        paths = list(DEFAULT_PATHS)
    found = []
    for src in sorted(set(sources(paths))):
        found += long_functions(src, args.n)
    found.sort(key=lambda r: (-r[0], r[1], r[2]))
    for lines, path, start, name in found:
        print(f"{lines:5d}  {path}:{start}  {name}")
    print(f"long-functions: {len(found)} function(s) over {args.n} lines", file=sys.stderr)
    return 1 if args.fail and found else 0


if __name__ == "__main__":
    sys.exit(main())
