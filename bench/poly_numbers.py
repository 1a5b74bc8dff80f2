"""The number lines of a Triangle or TetGen .poly file, shared by the peer
benchmark helpers (peers2d/poly2d.py, peers3d/poly3d.py)."""


def number_lines(path):
    """Yields each line that holds numbers as a list of floats; '#' starts a comment."""
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                yield [float(w) for w in words]
