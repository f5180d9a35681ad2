"""Python values to what the native module reads, exactly: the text of every number (ints
in full, floats and Fractions as ``p/q``, Decimals and strings as written), the machine bytes
of integer and float arrays, and the rows of a batch with the messages of those that cannot
be read. Errors are :class:`QsicError` naming what the value is (the callers add where)."""

from __future__ import annotations

import operator
from collections.abc import Iterable
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, List, Optional, Tuple

import numpy as np

from . import _qsic
from ._qsic import QsicError


def describe(x: Any) -> str:
    """``x`` for an error message: its type and a short repr (never raising)."""
    if x is None:
        return "None"
    try:
        text = repr(x)
    except Exception:
        return f"a {type(x).__name__}"
    if len(text) > 40:
        text = text[:37] + "..."
    return f"a {type(x).__name__} ({text})"


def int_text(n: int) -> str:
    """The decimal text of ``n``; past Python's ``str()`` limit for integers (4300 digits by
    default) through ``Decimal``, which converts exactly without it; an integer certainly
    beyond the library's digit limit is refused before any conversion."""
    bits = n.bit_length()
    if bits <= 14_000:  # below 4300 digits
        return str(n)
    if bits > 4 * _qsic.MAX_NUMBER_DIGITS:  # 4 bits > 1 digit: more digits than the limit
        raise QsicError(
            f"is an integer of {bits} bits: input exceeds a limit: more than "
            f"{_qsic.MAX_NUMBER_DIGITS} digits in one number (limit {_qsic.MAX_NUMBER_DIGITS})"
        )
    return str(Decimal(n))


def fraction(text: str) -> Fraction:
    """The ``Fraction`` of an exact text ``p`` or ``p/q`` of the library; integers past
    Python's ``int()`` limit for strings read through ``Decimal``, which has none."""
    if len(text) <= 4000:
        return Fraction(text)
    p, _, q = text.partition("/")
    return Fraction(int(Decimal(p)), int(Decimal(q)) if q else 1)


#: The readings of a float: ``"binary"`` (the default), the value the float holds exactly
#: (0.1 is 3602879701896397/2**55); ``"shortest"``, the shortest decimal that rounds to it,
#: the one ``repr`` prints (0.1 is 1/10, ``0.3**2`` is 9/100).
FLOAT_READINGS = ("binary", "shortest")


def check_floats(floats: Any) -> str:
    """``floats`` checked: one of :data:`FLOAT_READINGS`."""
    if not isinstance(floats, str) or floats not in FLOAT_READINGS:
        raise QsicError(f"floats must be 'binary' or 'shortest', got {floats!r}")
    return floats


def _shortest(x: Any) -> Optional[str]:
    """The shortest decimal text of a float that rounds to it (``repr`` for a Python float,
    NumPy's ``str`` — shortest for the scalar's own precision — for a NumPy float); None
    for anything that is not a float."""
    # NumPy first: np.float64 is a float, and its repr is "np.float64(…)" since NumPy 2
    if isinstance(x, np.floating):
        if not np.isfinite(x):
            raise QsicError("is not a finite number")
        return str(x)
    if isinstance(x, float):
        if x != x or x in (float("inf"), float("-inf")):
            raise QsicError("is not a finite number")
        return repr(x)
    return None


def entry_text(x: Any, floats: str = "binary") -> str:
    """An exact text for one number: ``str`` as written, integers in full, a ``Decimal`` as
    its text, anything with ``as_integer_ratio`` (float, Fraction, NumPy floats) as ``p/q``;
    with ``floats="shortest"`` a float as the shortest decimal that rounds to it.

    Raises:
        QsicError: the entry is not a finite real number or a string (the message says what
            it is, without the entry's position: the callers add it).
    """
    if isinstance(x, str):
        if not str.isascii(x):
            try:
                str.encode(x, "utf-8")
            except UnicodeEncodeError:
                raise QsicError("is a str that is not valid Unicode (a lone surrogate)") from None
        return x
    if isinstance(x, (bool, np.bool_)):
        raise QsicError(f"is {describe(x)}, not a number")
    if isinstance(x, int):
        return int_text(int(x))
    if isinstance(x, (bytes, bytearray, np.bytes_)):
        raise QsicError(f"is {describe(x)}, not a number or a str (decode it first)")
    if isinstance(x, (complex, np.complexfloating)):
        raise QsicError(f"is {describe(x)}, a complex number, not a real one")
    if isinstance(x, Decimal):
        if not x.is_finite():
            raise QsicError("is not a finite number")
        return str(x)  # the library reads its exponent, within its limits
    try:
        return int_text(operator.index(x))
    except TypeError:
        pass
    except Exception as e:
        raise QsicError(f"is {describe(x)} that could not be read ({type(e).__name__}: {e})") from None
    if floats == "shortest":
        text = _shortest(x)
        if text is not None:
            return text
    ratio = getattr(x, "as_integer_ratio", None)
    if ratio is None:
        raise QsicError(f"is {describe(x)}, not a number or a number string")
    try:
        p, q = ratio()
    except (ValueError, OverflowError):
        raise QsicError("is not a finite number") from None  # nan, inf
    except Exception as e:
        raise QsicError(f"is {describe(x)} that could not be read ({type(e).__name__}: {e})") from None
    if not (isinstance(p, int) and isinstance(q, int) and q > 0):
        raise QsicError(f"is {describe(x)} whose as_integer_ratio() is not two integers")
    return int_text(p) if q == 1 else f"{int_text(p)}/{int_text(q)}"


def matrix_texts(m: Any, floats: str = "binary") -> List[str]:
    """The 16 entry texts of a 4×4 matrix, row by row.

    Raises:
        QsicError: ``m`` is not a 4×4 matrix, or an entry (named by its position) is not a
            number.
    """
    if isinstance(m, np.ndarray):
        arr = m
    else:
        try:
            arr = np.asarray(m, dtype=object)
        except Exception:
            raise QsicError(f"a quadric matrix must be 4x4, got {describe(m)}") from None
    if arr.shape != (4, 4):
        got = describe(m) if arr.ndim == 0 else f"shape {arr.shape}"
        raise QsicError(f"a quadric matrix must be 4x4, got {got}")
    return entry_texts(items(arr.ravel()), floats)


def items(arr: np.ndarray) -> List[Any]:
    """The items of ``arr`` along its first axis: the objects of an object array, else NumPy
    scalars (not ``tolist()``'s Python values, which would make a ``timedelta64[ns]`` an
    int and a ``longdouble`` a float)."""
    return arr.tolist() if arr.dtype == object else list(arr)


_SHORT_INT = 10**18


def entry_texts(entries: List[Any], floats: str = "binary") -> List[str]:
    """The texts of a matrix's 16 entries, row by row (plain ints and ASCII strings taken as
    they are, the rest by :func:`entry_text`).

    Raises:
        QsicError: an entry, named by its position, is not a number.
    """
    texts = []
    for k, x in enumerate(entries):
        t = type(x)
        if t is int and -_SHORT_INT < x < _SHORT_INT:
            texts.append(str(x))
        elif t is str and x.isascii():
            texts.append(x)
        else:
            try:
                texts.append(entry_text(x, floats))
            except QsicError as e:
                raise QsicError(f"entry ({k // 4},{k % 4}) {e}") from None
    return texts


def number_text(x: Any, what: str, floats: str = "binary") -> str:
    """``entry_text(x, floats)``, its error naming ``what`` the number is."""
    try:
        return entry_text(x, floats)
    except QsicError as e:
        raise QsicError(f"{what} {e}") from None


def vector(v: Any, what: str, floats: str = "binary") -> List[str]:
    """The texts of the coordinates of ``v``, errors naming ``what`` and the coordinate."""
    return [
        number_text(x, f"{what}, coordinate {k},", floats)
        for k, x in enumerate(np.asarray(v, dtype=object).ravel())
    ]


_I64_MAX = np.iinfo(np.int64).max


def machine_side(arr: np.ndarray, floats: str = "binary") -> Optional[Tuple[str, bytes]]:
    """The kind and native bytes of an ``(N, 4, 4)`` array the library reads without texts:
    integers that fit in ``int64``, floats that fit in ``float64`` exactly (with
    ``floats="shortest"`` ``float64`` only: the shortest decimal of a narrower float is not
    that of its ``float64`` value); None otherwise."""
    kind = arr.dtype.kind
    if kind in "ib" or (kind == "u" and not (arr.size and arr.max() > _I64_MAX)):
        return "int64", np.ascontiguousarray(arr, dtype=np.int64).tobytes()
    if kind == "f" and floats == "shortest":
        if arr.dtype.itemsize != 8:
            return None
        return "float64_shortest", np.ascontiguousarray(arr, dtype=np.float64).tobytes()
    if kind == "f" and arr.dtype.itemsize <= 8:  # not long double: float64 would round it
        return "float64", np.ascontiguousarray(arr, dtype=np.float64).tobytes()
    return None


def batch_side(name: str, m: Any, floats: str = "binary") -> Tuple[str, Any, int]:
    """One side of a batch for ``_qsic.classify_many``: machine bytes for integer and float
    arrays, else the rows' entry texts with the errors of the rows that cannot be read.

    Raises:
        TypeError: ``m`` is not a sequence of rows.
        QsicError: an array whose shape is not ``(N, 4, 4)`` (every row would be wrong).
    """
    if isinstance(m, np.ndarray):
        if m.ndim == 3 and m.shape[1:] == (4, 4):
            machine = machine_side(m, floats)
            if machine is not None:
                return (*machine, m.shape[0])
            return text_side(items(m.reshape(-1, 16)), lambda r: entry_texts(r, floats))
        if m.ndim == 1 and m.dtype == object:  # a sequence of rows, each read alone
            return text_side(list(m), lambda r: matrix_texts(r, floats))
        if m.ndim == 0:
            raise TypeError(f"{name}: expected a sequence of 4x4 matrices, got {describe(m)}")
        raise QsicError(f"{name}: expected an array of shape (N, 4, 4), got {m.shape}")
    if isinstance(m, (str, bytes, bytearray, dict, set, frozenset)) or not isinstance(
        m, Iterable
    ):
        raise TypeError(
            f"{name}: expected a sequence of 4x4 matrices (an array of shape (N, 4, 4)), "
            f"got {describe(m)}"
        )
    return text_side(list(m), lambda r: matrix_texts(r, floats))


def text_side(rows: List[Any], read: Any) -> Tuple[str, Any, int]:
    """The texts of ``read(row)`` for every row, and the messages of the rows it refuses."""
    texts: List[str] = []
    errors: Dict[int, str] = {}
    for k, row in enumerate(rows):
        try:
            texts.extend(read(row))
        except QsicError as e:
            texts.extend(_ZERO_ROW)
            errors[k] = str(e)
    return "text", (texts, errors), len(rows)


_ZERO_ROW = ["0"] * 16  # the texts of a row that cannot be read (its error answers it)
