#!/usr/bin/env python3
"""Rewrites the option tables of docs/cli.md and docs/methods.md between their marker lines from
`curvbench methods --options --markdown flags|spellings` (tests/methods/test_option_docs.cpp
checks them).  Usage: tools/option_docs.py [path to the curvbench binary, default build/curvbench]"""
import subprocess
import sys

binary = sys.argv[1] if len(sys.argv) > 1 else "build/curvbench"
for doc, marker, style in [("docs/cli.md", "option table", "flags"),
                           ("docs/methods.md", "option spellings", "spellings")]:
    table = subprocess.run([binary, "methods", "--options", "--markdown", style],
                           capture_output=True, text=True, check=True).stdout
    text = open(doc).read()
    begin, end = f"<!-- {marker}: begin -->\n", f"<!-- {marker}: end -->"
    a, b = text.index(begin) + len(begin), text.index(end)
    open(doc, "w").write(text[:a] + table + text[b:])
