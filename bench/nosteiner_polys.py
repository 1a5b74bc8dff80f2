#!/usr/bin/env python3
"""Inputs for the no-boundary-Steiner benchmarks (bench/run_nosteiner.sh,
bench/series_nosteiner.sh): a regular N-gon on the unit circle as a Triangle
.poly. usage: nosteiner_polys.py ngon N OUT.poly"""
import math
import sys


def ngon(path, n):
    with open(path, "w") as f:
        f.write(f"# regular {n}-gon on the unit circle (bench/nosteiner_polys.py)\n{n} 2 0 0\n")
        for i in range(n):
            a = 2 * math.pi * i / n
            f.write(f"{i + 1} {math.cos(a)!r} {math.sin(a)!r}\n")
        f.write(f"{n} 0\n")
        for i in range(n):
            f.write(f"{i + 1} {i + 1} {(i + 1) % n + 1}\n")
        f.write("0\n")


if __name__ == "__main__":
    if len(sys.argv) != 4 or sys.argv[1] != "ngon":
        sys.exit(__doc__)
    ngon(sys.argv[3], int(sys.argv[2]))
