"""The exceptions pqmesh raises, one class per error class of the C++ library
(include/pqmesh/errors.hpp). str(exception) is the library's message, the text
the pqmesh CLI prints after "pqmesh COMMAND: ", e.g.
"square.poly:9: error [index-out-of-range]: segments 3 refer to vertex ids that do not exist".
"""


class Error(Exception):
    """Base of every pqmesh error (pqmesh::Error)."""


class InputError(Error, ValueError):
    """Bad input (pqmesh::InvalidInput; the CLI's exit code 2).

    code   -- stable name of the error ("index-out-of-range", "open-boundary", ...)
    ids    -- the offending ids (vertices, segments, facets: ``detail`` says which),
              in the file's own numbering when the input came from a file
    path   -- the input file, None when the input was built in memory
    line   -- 1-based line in ``path`` of the first offending entity, None when unknown
    detail -- the message without the "path:line: error [code]: " prefix
    """

    def __init__(self, message, code=None, ids=(), path=None, line=None, detail=None):
        super().__init__(message)
        self.code = code
        self.ids = list(ids)
        self.path = path
        self.line = line
        self.detail = message if detail is None else detail


class ParseError(InputError):
    """A file that cannot be read as the format it claims (pqmesh::ParseError)."""


class DomainError(InputError):
    """A domain that violates the mesher's assumptions (pqmesh::DomainError)."""


class MeshNotSupported(InputError):
    """A valid domain with a configuration the 3D box code does not handle
    (pqmesh::MeshNotSupported, code "unsupported"); ``kind`` is the leaf kind."""

    def __init__(self, message, code=None, ids=(), path=None, line=None, detail=None, kind=None):
        super().__init__(message, code, ids, path, line, detail)
        self.kind = kind


class OutputError(Error, OSError):
    """An output file that cannot be written (pqmesh::OutputError)."""


class InternalError(Error, RuntimeError):
    """A broken internal invariant: a bug in pqmesh (pqmesh::InternalError)."""
