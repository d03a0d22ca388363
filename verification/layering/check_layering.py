#!/usr/bin/env python3
"""The layering rule of CONTRIBUTING.md ("Architecture"): the library's sources live in one
folder per layer, lowest first,

    core, os, io, contact, model, time, scene, analysis, app,

and a module may use modules of its own folder (sub-folders included) and of earlier folders,
never of a later one. This program reads every Fortran source under SRC, finds the folder of
every module it defines and every `use` of a module of the library, and lists each use that
goes to a later folder. Each layer folder has a README.md, its map, that names every source
file of the folder (sub-folders included, as `path/in/folder.f90` in backquotes) and no file
that is not there. It exits 1 when a use goes against the order, a source file is outside
the folders, a folder is not in the list, or a map misses a file or names a missing one; 0
otherwise.

usage: check_layering.py SRC
"""
import os
import re
import sys

ORDER = ["core", "os", "io", "contact", "model", "time", "scene", "analysis", "app"]
MODULE = re.compile(r"^\s*module\s+(\w+)\s*(?:!.*)?$", re.I | re.M)
USE = re.compile(r"^\s*use\s*(?:,\s*(?:non_)?intrinsic\s*)?(?:::)?\s*(\w+)", re.I | re.M)


def strip_comments(text):
    # a '!' outside a string starts a comment; the sources keep '!' out of strings on use lines,
    # so cutting at the first '!' of a line is enough for module and use statements
    return "\n".join(line.split("!", 1)[0] for line in text.splitlines())


def main(argv):
    if len(argv) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    src = argv[1]
    problems = []
    folder_of = {}      # module name -> top folder
    uses = []           # (file, top folder, used module, line number)
    for root, dirs, files in os.walk(src):
        dirs.sort()
        for name in sorted(files):
            if not re.search(r"\.(f90|F90|c|f90\.in)$", name):
                continue
            path = os.path.join(root, name)
            relative = os.path.relpath(path, src)
            parts = relative.split(os.sep)
            if len(parts) == 1:
                problems.append(f"{relative}: a source file outside the layer folders")
                continue
            top = parts[0]
            if top not in ORDER:
                problems.append(f"{relative}: folder '{top}' is not a layer ({', '.join(ORDER)})")
                continue
            if name.endswith(".c"):
                continue
            with open(path, encoding="utf-8", errors="replace") as handle:
                text = strip_comments(handle.read())
            for match in MODULE.finditer(text):
                if match.group(1).lower() != "procedure":
                    folder_of[match.group(1).lower()] = top
            for match in USE.finditer(text):
                line = text.count("\n", 0, match.start()) + 1
                uses.append((relative, top, match.group(1).lower(), line))
    problems += check_maps(src)
    for relative, top, used, line in uses:
        if used not in folder_of:
            continue    # an intrinsic or external module (iso_c_binding, hdf5, mpi_f08, omp_lib)
        if ORDER.index(folder_of[used]) > ORDER.index(top):
            problems.append(f"{relative}:{line}: uses {used}, which is in {folder_of[used]}/, a later layer than {top}/")
    if problems:
        print(f"layering: {len(problems)} problem(s); the order is {' < '.join(ORDER)}")
        print("\n".join(problems))
        return 1
    print(f"layering: {len(uses)} uses of {len(folder_of)} modules checked, every one goes to its own or an earlier layer")
    return 0


SOURCE = re.compile(r"\.(f90|F90|c)$")
NAMED = re.compile(r"`([\w/]+\.(?:f90|F90|c))`")


def check_maps(src):
    """The README.md of each layer folder names exactly the folder's source files."""
    problems = []
    for top in ORDER:
        folder = os.path.join(src, top)
        if not os.path.isdir(folder):
            continue
        present = set()
        for root, dirs, files in os.walk(folder):
            for name in files:
                if SOURCE.search(name):
                    present.add(os.path.relpath(os.path.join(root, name), folder).replace(os.sep, "/"))
        readme = os.path.join(folder, "README.md")
        if not os.path.isfile(readme):
            problems.append(f"{top}/README.md: missing (the map of the folder's sources)")
            continue
        with open(readme, encoding="utf-8") as handle:
            named = set(NAMED.findall(handle.read()))
        for name in sorted(present - named):
            problems.append(f"{top}/README.md: does not name {name}")
        for name in sorted(named - present):
            problems.append(f"{top}/README.md: names {name}, which is not in {top}/")
    return problems


if __name__ == "__main__":
    sys.exit(main(sys.argv))
