#!/usr/bin/env python3
"""Bitwise comparison of two vibrobeam result files (HDF5), for refactorings that must not
change any result: every group, dataset and attribute of each file must exist in the other
with the same type, shape and bytes. Only what describes the process rather than the
result is left out: /run run_id, wall_seconds and peak_memory_kb, the root attribute
`program` (the path of the executable) and a sweep's /sweep/wall_seconds (per point).

usage: compare_results.py A.h5 B.h5     exit 0 identical, 1 different (each difference
                                        listed), 2 a file cannot be read
       compare_results.py --text A.dat B.dat   the same for two text files (after line 1,
                                        the run id), with VIBROBEAM_NEW_OUTPUTS as below
Needs h5py (Debian python3-h5py).

A change that adds input variables adds their defaults to what a result lists about its
input (the root attributes 'group.variable' and the lines of /run resolved_input). With
VIBROBEAM_NEW_INPUTS set to names or prefixes separated by blanks ('forces.' for a new
group), those attributes and lines are left out on both sides, so that everything else
can still be compared bit for bit.

A change that adds outputs (datasets, attributes, checkpoint items, text columns) while
every earlier one must stay bit for bit: VIBROBEAM_NEW_OUTPUTS set to path prefixes
separated by blanks ('/statistics/poincare/period', or 'statistics.diagnostics.' for the
checkpoint items of that name) lets objects of those names exist in B only (an object is
new when its path, or its last component, starts with a prefix), compares /checkpoint's
`items` without them and leaves out each checkpoint slot's `checksum` (it covers the new
items; every old item is compared itself). Text files: every line of A must begin B's
line, B having more column lines ('# 46: ...') after A's last (columns appended).
"""
import os
import sys

import h5py
import numpy

VOLATILE = {("/run", "run_id"), ("/run", "wall_seconds"), ("/run", "peak_memory_kb"), ("/", "program")}
VOLATILE_DATASETS = {"/sweep/wall_seconds"}
NEW_INPUTS = tuple(os.environ.get("VIBROBEAM_NEW_INPUTS", "").split())
NEW_OUTPUTS = tuple(os.environ.get("VIBROBEAM_NEW_OUTPUTS", "").split())


def new_output(path):
    """An object the change adds (VIBROBEAM_NEW_OUTPUTS)."""
    return bool(NEW_OUTPUTS) and (path.startswith(NEW_OUTPUTS) or path.rsplit("/", 1)[-1].startswith(NEW_OUTPUTS))


def without_new_items(value):
    """/checkpoint items without the new items."""
    text = value.decode() if isinstance(value, bytes) else str(value)
    return " ".join(token for token in text.split() if not token.startswith(NEW_OUTPUTS))


def new_input(name):
    """An input variable the change adds (VIBROBEAM_NEW_INPUTS)."""
    return bool(NEW_INPUTS) and name.startswith(NEW_INPUTS)


def without_new_inputs(value):
    """resolved_input without the lines of the new input variables."""
    if not NEW_INPUTS:
        return value
    text = value.decode() if isinstance(value, bytes) else str(value)
    return "\n".join(line for line in text.split("\n") if not new_input(line.strip()))


def items(handle):
    """Every object of the file: path -> (kind, object)."""
    found = {"/": handle}
    handle.visititems(lambda name, obj: found.__setitem__("/" + name, obj))
    return found


def same_bytes(a, b):
    a, b = numpy.asarray(a), numpy.asarray(b)
    if a.dtype != b.dtype or a.shape != b.shape:
        return False
    if a.dtype.kind in "OSU":   # strings: compare as Python values
        return a.tolist() == b.tolist()
    return a.tobytes() == b.tobytes()


def compare(path_a, path_b):
    differences = []
    with h5py.File(path_a, "r") as file_a, h5py.File(path_b, "r") as file_b:
        objects_a, objects_b = items(file_a), items(file_b)
        for path in sorted(set(objects_a) | set(objects_b)):
            if path not in objects_a and new_output(path):
                continue
            if path not in objects_b or path not in objects_a:
                differences.append(f"{path}: only in {'A' if path in objects_a else 'B'}")
                continue
            a, b = objects_a[path], objects_b[path]
            if type(a) is not type(b):
                differences.append(f"{path}: a {type(a).__name__} in A, a {type(b).__name__} in B")
                continue
            if isinstance(a, h5py.Dataset) and path not in VOLATILE_DATASETS and not same_bytes(a[()], b[()]):
                differences.append(f"{path}: the values differ (A {a.dtype}{a.shape}, B {b.dtype}{b.shape})")
            for name in sorted(set(a.attrs) | set(b.attrs)):
                if (path, name) in VOLATILE or new_input(name):
                    continue
                if NEW_OUTPUTS and name == "checksum" and path.startswith("/checkpoint/state_"):
                    continue
                if NEW_OUTPUTS and (path, name) == ("/checkpoint", "items") and name in a.attrs and name in b.attrs:
                    if without_new_items(a.attrs[name]) != without_new_items(b.attrs[name]):
                        differences.append(f"{path} attribute {name}: differs beyond the new items")
                    continue
                if name not in a.attrs or name not in b.attrs:
                    differences.append(f"{path} attribute {name}: only in {'A' if name in a.attrs else 'B'}")
                elif name == "resolved_input" and NEW_INPUTS:
                    if without_new_inputs(a.attrs[name]) != without_new_inputs(b.attrs[name]):
                        differences.append(f"{path} attribute {name}: differs beyond the new inputs")
                elif not same_bytes(a.attrs[name], b.attrs[name]):
                    differences.append(f"{path} attribute {name}: {a.attrs[name]!r} in A, {b.attrs[name]!r} in B")
    return differences


def compare_text(path_a, path_b):
    """Every line of A (after line 1) begins the same line of B; B may have more column
    lines after A's last when NEW_OUTPUTS allows new outputs."""
    with open(path_a) as handle:
        lines_a = handle.read().splitlines()[1:]
    with open(path_b) as handle:
        lines_b = handle.read().splitlines()[1:]
    if not NEW_OUTPUTS:
        return [] if lines_a == lines_b else [f"{path_b}: differs from {path_a}"]
    def column(line):
        words = line.split()
        return int(words[1][:-1]) if line.startswith("# ") and len(words) > 1 and words[1][:-1].isdigit() \
            and words[1].endswith(":") else 0
    last = max([column(line) for line in lines_a] + [0])
    if last > 0:
        lines_b = [line for line in lines_b if column(line) <= last]
    if len(lines_a) != len(lines_b):
        return [f"{path_b}: {len(lines_b)} lines, {path_a} {len(lines_a)}"]
    return [f"{path_b} line {k + 2} does not begin with {path_a}'s" for k, (a, b) in enumerate(zip(lines_a, lines_b))
            if not b.startswith(a)][:10]


def main(argv):
    if len(argv) == 4 and argv[1] == "--text":
        differences = compare_text(argv[2], argv[3])
        print("\n".join(differences))
        return 1 if differences else 0
    if len(argv) != 3:
        print(__doc__, file=sys.stderr)
        return 2
    try:
        differences = compare(argv[1], argv[2])
    except OSError as error:
        print(f"compare_results: {error}", file=sys.stderr)
        return 2
    if differences:
        print(f"{argv[1]} and {argv[2]} differ in {len(differences)} place(s):")
        print("\n".join(differences[:50]))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
