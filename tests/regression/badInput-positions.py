#!/usr/bin/python3
"""The broken input of tests/regression/badInput-positions.sh: moves two of
the manualInjection's positions (elements 4 and 8 of the 3200 in
constant/kinematicCloudPositions) outside the settling column's mesh, to
(0.5 0.2 0.0025) and (0.02 -0.1 0.0025); the script then checks that
mppicPimpleFoam refuses them (check fatal) and that ignoreOutOfBounds yes
drops them.

Usage: badInput-positions.py <positions file>   (rewritten in place)
"""
import re
import sys


def move_two_positions_outside(path):
    """Elements 4 and 8 of the positions list moved outside the mesh; the
    file's header kept, the list written one position a line."""
    text = open(path).read()
    body = text[text.index("}") + 1:]
    points = re.findall(r"\(([^()]+)\)", body)
    points[4] = "0.5 0.2 0.0025"
    points[8] = "0.02 -0.1 0.0025"
    head = text[:text.index("}") + 1]
    open(path, "w").write(head + "\n\n%d\n(\n%s\n)\n" % (
        len(points), "\n".join("(%s)" % p for p in points)))


if __name__ == "__main__":
    move_two_positions_outside(sys.argv[1])
