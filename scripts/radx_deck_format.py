"""Fixed-column cells of the Radioss block format (docs/theory/deck-format.md), shared by the deck generators.

The cells under scripts/radx_cards.py (the one card writer of the generators), the ruler, the /BCS and IBC
code cells and the file writer; scripts/make_version_decks.py restates the old layouts with fmt_real on
purpose. A data line is a row of cells, each right-justified in its field (10 columns for an integer, 20 for
a real, as the card says). Every helper raises ValueError rather than write a value that does not fit its
field.

Plain python3, standard library only.
"""
import os

RULER = ("#---1----|----2----|----3----|----4----|----5----|----6----|"
         "----7----|----8----|----9----|---10----|")


def fmt_real(v, w=20, sig=None):
    """Text of a real: a string as it is, else the shortest text that reads back as the same double
    (Fortran-readable). With sig, a text longer than w - 1 columns (no blank left before it) falls back
    to sig significant digits."""
    if isinstance(v, str):
        return v
    s = repr(float(v))
    if sig is not None and len(s) > w - 1:
        s = "%.*g" % (sig, v)
    return s


def I(v, w=10):
    """Integer cell (None: blank; a string is written as it is, e.g. a deliberately bad value)."""
    s = "" if v is None else (v if isinstance(v, str) else str(int(v)))
    if len(s) > w:
        raise ValueError(f"integer {s!r} does not fit in {w} columns")
    return s.rjust(w)


def R(v, w=20, sig=None):
    """Real cell (None: blank; a string is written as it is). sig: see fmt_real."""
    s = "" if v is None else fmt_real(v, w, sig)
    if len(s) > w:
        raise ValueError(f"real {s!r} does not fit in {w} columns")
    return s.rjust(w)


def S(v, w):
    """String cell, right-justified like the numbers."""
    s = "" if v is None else str(v)
    if len(s) > w:
        raise ValueError(f"string {s!r} does not fit in {w} columns")
    return s.rjust(w)


def bcs_code(t, r):
    """/BCS columns 1-10: blank 1-3, Tx Ty Tz at 4-6, blank 7, Rx Ry Rz at 8-10."""
    return "   " + t + " " + r


def ibc_code(x, y, z):
    """TYPE7 IBC: one digit each at columns 8, 9, 10."""
    return "       " + str(x) + str(y) + str(z)


def write(path, lines, report=False):
    """Write the lines (each may hold embedded newlines) with LF endings and a final newline, creating the
    folder. With report, print 'wrote PATH (N lines)'."""
    folder = os.path.dirname(path)
    if folder:
        os.makedirs(folder, exist_ok=True)
    with open(path, "w", newline="\n") as f:
        f.write("\n".join(lines) + "\n")
    if report:
        print("wrote %s (%d lines)" % (path, len(lines)))
