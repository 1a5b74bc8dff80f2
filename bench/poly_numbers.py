"""The number lines of a Triangle or TetGen .poly file, shared by the peer
benchmark helpers (peers2d/poly2d.py, peers3d/poly3d.py)."""


def number_lines(path):
    """Yields each line that holds numbers as a list of floats; '#' starts a comment."""
    with open(path) as f:
        for line in f:
            words = line.split("#", 1)[0].split()
            if words:
                yield [float(w) for w in words]


def read_nodes(lines, dims):
    """Reads a node section from number_lines: the count line, then one line a
    vertex (id, dims coordinates, attributes and markers skipped). Returns the
    coordinate tuples and the first vertex id (0 or 1), by which the files'
    later vertex references are offset."""
    n = int(next(lines)[0])
    vertices, first_id = [], 0
    for i in range(n):
        v = next(lines)
        if i == 0:
            first_id = int(v[0])
        vertices.append(tuple(v[1:1 + dims]))
    return vertices, first_id
