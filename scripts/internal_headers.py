#!/usr/bin/env python3
"""Lists the headers of common/ that could be INTERNAL to their module (docs/architecture.md).

A header can be internal when nothing outside its module includes it: no other module, no executable,
tool, benchmark or fuzz target, no test but the module's own (tests/<module>/), and no public header of its
own module (whose users would then need it); tests/tooling/'s probes, which include an internal header on
purpose to prove it is refused, do not count. Compare the output with the INTERNAL lists of the ks_module(...)
lines in CMakeLists.txt. Run from anywhere: python3 scripts/internal_headers.py

With --check (the test tooling/internal_headers) it compares instead and fails, naming the fix, when a header
that could be internal is not listed, or a listed one is included from outside its module.
"""
import os
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^">]+)[">]', re.MULTILINE)
FOLDERS = ["common", "editor", "runtime", "tests", "bench", "fuzz", "assets"]


def sources():
    for folder in FOLDERS:
        for directory, _, names in os.walk(os.path.join(ROOT, folder)):
            for name in names:
                path = os.path.relpath(os.path.join(directory, name), ROOT).replace(os.sep, "/")
                if name.endswith((".h", ".hpp", ".inl", ".cpp", ".cc")) and not path.startswith("tests/tooling/"):
                    yield path


def listed_internal():
    """The INTERNAL lists of the ks_module(...) calls in CMakeLists.txt, as module/header."""
    with open(os.path.join(ROOT, "CMakeLists.txt"), encoding="utf-8") as f:
        text = f.read()
    listed = set()
    for module, arguments in re.findall(r"ks_module\(\s*(\w+)([^)]*)\)", text):
        words = arguments.split()
        if "INTERNAL" in words:
            listed.update(f"{module}/{h}" for h in words[words.index("INTERNAL") + 1:])
    return listed


def check(internal):
    listed = listed_internal()
    problems = [f"common/{h} is included only inside its module: add {h.split('/')[1]} to INTERNAL in "
                f"ks_module({h.split('/')[0]} ...) in CMakeLists.txt" for h in sorted(set(internal) - listed)]
    problems += [f"common/{h} is listed as INTERNAL but is included from outside its module (or by one of its "
                 f"public headers): remove it from the list, or that include" for h in sorted(listed - set(internal))]
    for problem in problems:
        print(problem)
    if not problems:
        print(f"the INTERNAL lists name exactly the {len(internal)} headers used only inside their module")
    return 1 if problems else 0


def main():
    common = os.path.join(ROOT, "common")
    headers = sorted(f"{m}/{h}" for m in os.listdir(common) if os.path.isdir(os.path.join(common, m))
                     for h in os.listdir(os.path.join(common, m)) if h.endswith(".h"))
    known = set(headers)
    public = set()
    included_by_header = {}  # module header -> headers of the same module it includes
    for path in sources():
        with open(os.path.join(ROOT, path), encoding="utf-8", errors="replace") as f:
            for included in INCLUDE.findall(f.read()):
                if included not in known:
                    continue
                module = included.split("/")[0]
                if path.startswith(f"common/{module}/"):
                    if path.endswith(".h"):
                        included_by_header.setdefault(path[len("common/"):], set()).add(included)
                elif not path.startswith(f"tests/{module}/"):
                    public.add(included)
    grown = True
    while grown:  # what a public header includes is public too
        grown = False
        for header in list(public):
            for included in included_by_header.get(header, ()):
                if included not in public:
                    public.add(included)
                    grown = True
    internal = [h for h in headers if h not in public]
    if "--check" in sys.argv[1:]:
        return check(internal)
    for header in internal:
        print(header)
    print(f"{len(internal)} of {len(headers)} headers could be internal", file=sys.stderr)
    return 0


if __name__ == "__main__":
    sys.exit(main())
