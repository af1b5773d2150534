#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""docs/cli.md's option reference, from `elastica COMMAND --help`.

    scripts/cli-reference.py ELASTICA                  print the reference (Markdown)
    scripts/cli-reference.py ELASTICA --check CLI.md   exit 1 unless CLI.md's reference lists, per
                                                       command, the options --help lists (names and
                                                       order), each once

The reference sits between the markers <!-- option-reference --> and <!-- /option-reference --> in
docs/cli.md; an entry is a line "- `-o`, `--output` `ARG`: what it does". The help is CLI11's: an option's
line starts with two spaces and '-', its text begins after two or more spaces (or on the next
line), and continuation lines are indented further.
"""
import re
import subprocess
import sys

COMMANDS = ("fair", "fill", "curvature", "generate", "subdivide", "run", "batch")
BEGIN, END = "<!-- option-reference -->", "<!-- /option-reference -->"


def help_options(exe, command):
    """[(names, argument, text)] of `exe command --help`, in its order, without -h/--help."""
    out = subprocess.run([exe, command, "--help"], check=True, capture_output=True, text=True).stdout
    options, in_options = [], False
    for line in out.splitlines():
        if line.startswith("Options:"):
            in_options = True
            continue
        if not in_options or not line.strip():
            continue
        if not line.startswith(" "):
            break  # the next section (Subcommands: ...)
        m = re.match(r"^  (-\S+)(?: (.*?))?(?:\s{2,}(.*))?$", line)
        if m:
            names = m.group(1)
            if names == "-h,--help":
                continue
            options.append([names, (m.group(2) or "").strip(), (m.group(3) or "").strip()])
        elif options:
            options[-1][2] = (options[-1][2] + " " + line.strip()).strip()
    return options


def long_name(names):
    """The option's long name (--output for -o,--output), which the reference is checked by."""
    longs = [n for n in names.split(",") if n.startswith("--")]
    return longs[0] if longs else names.split(",")[0]


def reference(exe):
    lines = [BEGIN]
    for command in COMMANDS:
        lines += ["", f"### `elastica {command}`", ""]
        for names, arg, text in help_options(exe, command):
            shown = ", ".join(f"`{n}`" for n in names.split(","))
            lines.append(f"- {shown}{' `' + arg + '`' if arg else ''}: {text}")
    lines += ["", END]
    return "\n".join(lines)


def documented(page):
    """{command: [long names]} of the reference in `page`."""
    text = open(page, encoding="utf-8").read()
    if BEGIN not in text or END not in text:
        sys.exit(f"cli-reference: no {BEGIN} ... {END} in {page}")
    block = text.split(BEGIN, 1)[1].split(END, 1)[0]
    found, command = {}, None
    for line in block.splitlines():
        m = re.match(r"^### `elastica (\w+)`", line)
        if m:
            command = m.group(1)
            found[command] = []
            continue
        m = re.match(r"^- ((?:`-[^`]+`(?:, )?)+)", line)
        if m and command:
            names = ",".join(re.findall(r"`(-[^`]+)`", m.group(1)))
            found[command].append(long_name(names))
    return found


def main():
    if len(sys.argv) == 2:
        print(reference(sys.argv[1]))
        return 0
    if len(sys.argv) != 4 or sys.argv[2] != "--check":
        sys.exit(__doc__.split("\n\n")[1])
    exe, page = sys.argv[1], sys.argv[3]
    doc, status = documented(page), 0
    for command in COMMANDS:
        wanted = [long_name(n) for n, _, _ in help_options(exe, command)]
        have = doc.get(command)
        if have != wanted:
            status = 1
            print(f"cli-reference: elastica {command}: {page} lists {have}, --help {wanted}", file=sys.stderr)
    for command in sorted(set(doc) - set(COMMANDS)):
        status = 1
        print(f"cli-reference: {page} has a section for elastica {command}, which is not a command here", file=sys.stderr)
    if status == 0:
        print(f"cli-reference: {page} lists every option of {', '.join(COMMANDS)} as --help does")
    return status


if __name__ == "__main__":
    sys.exit(main())
