"""Exact classification of the intersection curve of two quadric surfaces (the QSIC).

Every sign, rank, multiplicity and root count is decided exactly; numbers are read exactly
(a float is the binary fraction it holds, 0.1 as a float is 3602879701896397/2**55; the
string "0.1" is one tenth; ``floats="shortest"`` reads a float as the decimal ``repr``
prints, 0.1 as one tenth).

>>> import qsic
>>> r = qsic.classify("x^2+y^2+z^2-1", "x^2+y^2-z^2")
>>> (r.pencil, r.case, r.real_type)
('regular', 14, 'two_nonsecant_conics')

The answers are the JSON objects of the ``qsic`` command line (README, "Result object"):
``classify(a, b).to_dict()`` equals ``qsic classify --json A B``.
"""

from __future__ import annotations

import json
import operator
from decimal import Decimal
from fractions import Fraction
from typing import Any, Dict, List, Optional, Sequence, Tuple, Union

import numpy as np

from . import _inputs, _qsic
from ._qsic import QsicError

__all__ = [
    "Quadric",
    "Classification",
    "QsicError",
    "classify",
    "classify_many",
    "param",
    "sample",
    "nurbs",
    "motion",
    "first_contact",
    "FIELDS",
    "MAX_THREADS",
    "DEFAULT_BUDGET",
]

#: The fields of a classification, in the order of the JSON result object.
FIELDS = (
    "pencil",
    "case",
    "segre",
    "signature",
    "index_sequence",
    "complex_type",
    "real_type",
    "components",
    "singular_points",
    "description",
)


QuadricLike = Union["Quadric", str, Sequence[Sequence[Any]], np.ndarray]


def _native(q: Any, floats: str = "binary") -> Optional[_qsic.NativeQuadric]:
    """The native quadric of anything a quadric can be given as; None for the zero form."""
    if isinstance(q, Quadric):
        return q._native
    if isinstance(q, str):
        return _qsic.quadric_from_text(q)
    if isinstance(q, np.ndarray) and q.shape == (4, 4) and q.dtype.kind in "iuf":
        # a machine array: its bytes, as classify_many reads a row (NaN and infinities go the
        # text way, for its message naming the entry)
        side = _inputs.machine_side(q, floats)
        if side is not None and (q.dtype.kind != "f" or np.isfinite(q).all()):
            return _qsic.quadric_from_machine(*side)
    return _qsic.quadric_from_entries(_inputs.matrix_texts(q, floats))


class Quadric:
    """A quadric surface ``XᵀAX = 0``, ``X = (x, y, z, w)``, ``A`` a symmetric 4×4 rational
    matrix, read exactly.

    ``Quadric(source)`` takes a polynomial string of degree 2 in ``x, y, z, w`` (homogeneous)
    or in ``x, y, z`` (affine, homogenized with ``w``; a polynomial of degree 1 is a plane,
    read as its double plane), or a 4×4 array whose entries are ints, floats, ``Fraction``s
    or number strings (``"3/4"``, ``"0.1"``, ``"-2.5e3"``).

    ``floats``: how a float is read. ``"binary"`` (the default): the value it holds, exactly
    (``0.1`` is 3602879701896397/2**55, as ``Fraction(0.1)``); ``"shortest"``: the shortest
    decimal that rounds to it, the one ``repr`` prints (``0.1`` is 1/10, ``0.3**2`` — printed
    ``0.09`` — is 9/100), i.e. the number as typed when it was typed as a literal. Strings,
    ints, ``Fraction``s and ``Decimal``s are read as written either way.

    Raises:
        QsicError: the library's message (syntax error with its column, entry ``(row,col)``,
            a matrix that is not symmetric, the zero form, a limit).
    """

    __slots__ = ("_native",)

    def __init__(self, source: QuadricLike, *, floats: str = "binary") -> None:
        native = _native(source, _inputs.check_floats(floats))
        if native is None:
            raise QsicError("the zero form is not a quadric")
        self._native = native

    @classmethod
    def _of(cls, native: _qsic.NativeQuadric) -> "Quadric":
        q = cls.__new__(cls)
        q._native = native
        return q

    @property
    def matrix(self) -> np.ndarray:
        """The symmetric matrix, a 4×4 object array of ``Fraction``s (as given, not rescaled)."""
        return np.array(
            [_inputs.fraction(t) for t in self._native.entries()], dtype=object
        ).reshape(4, 4)

    @property
    def polynomial(self) -> str:
        """The quadratic form as a polynomial string in ``x, y, z, w``."""
        return self._native.polynomial()

    @property
    def is_plane(self) -> bool:
        """Given as a polynomial of degree 1: a plane, the quadric its double plane."""
        return self._native.is_plane()

    def __str__(self) -> str:
        return self.polynomial

    def __repr__(self) -> str:
        return f"Quadric({self.polynomial!r})"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Quadric) and self._native.equals(other._native)

    __hash__ = None  # type: ignore[assignment]

    # Shapes (module qsic::shapes of the Rust library). Lengths enter squared, so every
    # coefficient stays rational; parameters are numbers as in the matrix entries, floats
    # read as ``floats`` says (``Quadric()``).

    @classmethod
    def _shape(cls, name: str, *args: Any, floats: str = "binary") -> "Quadric":
        floats = _inputs.check_floats(floats)
        texts = [
            _inputs.vector(a, f"argument {k} of {name}", floats)
            if np.ndim(a) > 0
            else [_inputs.number_text(a, f"argument {k} of {name}", floats)]
            for k, a in enumerate(args)
        ]
        return cls._of(_qsic.quadric_from_shape(name, texts))

    @classmethod
    def sphere(cls, center: Sequence[Any], r2: Any, *, floats: str = "binary") -> "Quadric":
        """The sphere ``|X − center|² = r2``."""
        return cls._shape("sphere", center, r2, floats=floats)

    @classmethod
    def ellipsoid(cls, center: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``Σ (Xᵢ − centerᵢ)²/a2ᵢ = 1`` with ``semi_axes2 = (a2₀, a2₁, a2₂)``."""
        return cls._shape("ellipsoid", center, semi_axes2, floats=floats)

    @classmethod
    def cylinder(cls, point: Sequence[Any], direction: Sequence[Any], r2: Any, *, floats: str = "binary") -> "Quadric":
        """The circular cylinder of squared radius ``r2`` about the line ``point + s·direction``."""
        return cls._shape("cylinder", point, direction, r2, floats=floats)

    @classmethod
    def elliptic_cylinder(cls, axis: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(x − x₀)²/a2 + (y − y₀)²/b2 = 1`` with ``axis = (x₀, y₀)``, ``semi_axes2 = (a2, b2)``."""
        return cls._shape("elliptic_cylinder", axis, semi_axes2, floats=floats)

    @classmethod
    def cone(cls, apex: Sequence[Any], direction: Sequence[Any], cos2: Any, *, floats: str = "binary") -> "Quadric":
        """The circular cone ``((X − apex)·v)² = cos2·|v|²·|X − apex|²`` (``cos2`` the squared
        cosine of the half-angle)."""
        return cls._shape("cone", apex, direction, cos2, floats=floats)

    @classmethod
    def elliptic_cone(cls, apex: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(x − x₀)²/a2 + (y − y₀)²/b2 = (z − z₀)²``."""
        return cls._shape("elliptic_cone", apex, semi_axes2, floats=floats)

    @classmethod
    def elliptic_paraboloid(cls, vertex: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(x − x₀)²/a2 + (y − y₀)²/b2 = z − z₀``."""
        return cls._shape("elliptic_paraboloid", vertex, semi_axes2, floats=floats)

    @classmethod
    def hyperbolic_paraboloid(cls, vertex: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(x − x₀)²/a2 − (y − y₀)²/b2 = z − z₀``."""
        return cls._shape("hyperbolic_paraboloid", vertex, semi_axes2, floats=floats)

    @classmethod
    def hyperboloid_one_sheet(cls, center: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(x − x₀)²/a2 + (y − y₀)²/b2 − (z − z₀)²/c2 = 1``."""
        return cls._shape("hyperboloid_one_sheet", center, semi_axes2, floats=floats)

    @classmethod
    def hyperboloid_two_sheets(cls, center: Sequence[Any], semi_axes2: Sequence[Any], *, floats: str = "binary") -> "Quadric":
        """``(z − z₀)²/c2 − (x − x₀)²/a2 − (y − y₀)²/b2 = 1``."""
        return cls._shape("hyperboloid_two_sheets", center, semi_axes2, floats=floats)

    @classmethod
    def plane_pair(cls, n1: Sequence[Any], d1: Any, n2: Sequence[Any], d2: Any, *, floats: str = "binary") -> "Quadric":
        """The plane pair ``(n1·X + d1)(n2·X + d2) = 0``."""
        return cls._shape("plane_pair", n1, d1, n2, d2, floats=floats)


class Classification:
    """The class of a pair of quadrics: the fields of the JSON result object (README,
    "Result object"), ``affine`` the ``"affine"`` object or None when left out.

    ``str(result)`` is the text report of ``qsic classify A B``; ``to_dict()`` the JSON object
    of ``qsic classify --json A B``.
    """

    __slots__ = ("_dict", "_text")

    def __init__(self, fields: Dict[str, Any], text: str = "") -> None:
        self._dict = fields
        self._text = text

    pencil = property(lambda self: self._dict["pencil"], doc="regular, singular or single")
    case = property(lambda self: self._dict["case"], doc="case 1–35 (regular pencils), else None")
    segre = property(lambda self: self._dict["segre"], doc="Segre characteristic, e.g. [(11)11]_3")
    signature = property(lambda self: self._dict["signature"], doc="canonical signature sequence")
    index_sequence = property(lambda self: self._dict["index_sequence"], doc="canonical index sequence")
    complex_type = property(lambda self: self._dict["complex_type"], doc="type over ℂ")
    real_type = property(lambda self: self._dict["real_type"], doc="what is real")
    components = property(lambda self: self._dict["components"], doc="real components, grouped")
    singular_points = property(lambda self: self._dict["singular_points"], doc="real singular points, grouped")
    description = property(lambda self: self._dict["description"], doc="one-line summary")
    affine = property(lambda self: self._dict.get("affine"), doc="the pair in ℝ³, or None")

    def to_dict(self) -> Dict[str, Any]:
        """The JSON result object as a dict (a fresh copy), keys in schema order."""
        return json.loads(json.dumps(self._dict))

    def __eq__(self, other: object) -> bool:
        return isinstance(other, Classification) and self._dict == other._dict

    __hash__ = None  # type: ignore[assignment]

    def __str__(self) -> str:
        return self._text.rstrip("\n")

    def __repr__(self) -> str:
        return (
            f"Classification(pencil={self.pencil!r}, case={self.case!r}, "
            f"complex_type={self.complex_type!r}, real_type={self.real_type!r})"
        )


def classify(
    a: QuadricLike,
    b: QuadricLike,
    *,
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Classification:
    """Classifies the intersection of ``a`` and ``b`` (each a :class:`Quadric` or anything
    ``Quadric()`` takes; one of them may be the zero form ``"0"``).

    ``affine=False`` leaves out the affine view (like ``--projective``: it builds the exact
    curve, far costlier than the classification); ``chart`` is the plane at infinity of the
    affine view, a linear form ``"a*x+b*y+c*z+d*w"`` (default ``"w"``); ``floats``: how the
    floats of a matrix are read, ``"binary"`` or ``"shortest"`` (``Quadric()``). ``budget``: the
    work units the call may spend (:data:`DEFAULT_BUDGET` by default; README, "Work budget").

    Raises:
        QsicError: a bad quadric (message prefixed ``A: ``/``B: ``), both zero, a budget
            that is not a positive integer, or ``over the work budget: …``.
    """
    floats = _inputs.check_floats(floats)
    na = _side_native("A", a, floats)
    nb = _side_native("B", b, floats)
    line, text = _qsic.classify(na, nb, affine=affine, chart=chart, budget=_budget(budget))
    return Classification(json.loads(line), text)


#: The work budget of one call, or of one row of :func:`classify_many`, when ``budget`` is
#: not given: the CLI's ``--line-budget`` default, 10¹² units (README, "Work budget").
DEFAULT_BUDGET: int = _qsic.DEFAULT_BUDGET


def _budget(budget: Any) -> Optional[int]:
    """``budget`` checked: None, or an integer from 1 to 2⁶⁴ − 1."""
    wanted = "budget must be a positive integer of work units, at most 2**64 - 1"
    return _int_in(budget, 2**64 - 1, wanted)


def _int_in(value: Any, most: int, wanted: str) -> Optional[int]:
    """``value`` checked: None, or an integer (not a bool) from 1 to ``most``; else
    :class:`QsicError` with ``wanted`` and what was given."""
    if value is None:
        return None
    if isinstance(value, (bool, np.bool_)):
        raise QsicError(f"{wanted}, got {value!r}")
    try:
        k = operator.index(value)
    except TypeError:
        raise QsicError(f"{wanted}, got {_inputs.describe(value)}") from None
    if not 1 <= k <= most:
        raise QsicError(f"{wanted}, got {k}")
    return k


def _side_native(name: str, q: Any, floats: str = "binary") -> Optional[_qsic.NativeQuadric]:
    try:
        return _native(q, floats)
    except QsicError as e:
        raise QsicError(f"{name}: {e}") from None


#: The most threads ``classify_many`` takes (256): beyond the cores threads only add start-up
#: and scheduling cost, and 256 is above the hardware threads of common machines while
#: starting them takes milliseconds (the bound is argued at ``MAX_THREADS`` in src/lib.rs).
MAX_THREADS: int = _qsic.MAX_THREADS


def _thread_count(threads: Any) -> Optional[int]:
    """``threads`` checked: None, or an integer from 1 to :data:`MAX_THREADS`."""
    return _int_in(threads, MAX_THREADS, f"threads must be an integer from 1 to {MAX_THREADS}")


def classify_many(
    A: Any,
    B: Any,
    *,
    affine: bool = False,
    chart: Optional[str] = None,
    threads: Optional[int] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Dict[str, np.ndarray]:
    """Classifies ``A[k]`` against ``B[k]`` for every ``k``, on all cores with the GIL released.

    ``A`` and ``B`` are ``(N, 4, 4)`` arrays: ``int64`` (or any integer type), ``float64``
    (or a narrower float; floats converted exactly), or any other array or sequence of N
    4×4 matrices whose entries are ints, floats, ``Fraction``s, ``Decimal``s and number
    strings, read entry by entry as ``Quadric()`` reads them (exact, slower than the machine
    arrays). A zero matrix is the zero form (allowed on one side, as in the CLI).

    Returns a dict of NumPy arrays of length N, in the order of the JSON result object:
    ``pencil``, ``segre``, ``signature``, ``index_sequence``, ``complex_type``,
    ``real_type``, ``description`` (object arrays of str or None), ``case`` (``int8``, 0
    where the pencil has no case), ``components``, ``singular_points`` (object arrays of
    lists of dicts), ``affine`` (dicts, only with ``affine=True``: the ``"affine"`` object of
    ``qsic classify``, costly) and ``error``: None, or the message of the row's error
    (``A: …``, ``B: …``, as in ``qsic classify --batch``; the other columns None, ``case``
    0). A bad row never raises, whatever it holds: a matrix that is not symmetric, a row that
    is not a 4×4 matrix (``A: a quadric matrix must be 4x4, got …``), an entry that is not a
    finite real number or a number string (``A: entry (0,1) is None, not a number``: None,
    bytes, complex, NaN, an object that cannot be read), a number beyond the library's limits.

    ``threads``: the number of threads, an integer from 1 to :data:`MAX_THREADS` (256);
    default: all cores. ``budget``: the work units each row may spend (a row over it has the
    error ``over the work budget: …``); default :data:`DEFAULT_BUDGET`. ``floats``:
    ``"binary"`` or ``"shortest"``, as for ``Quadric()`` (``float64`` arrays read in Rust
    either way).

    Raises:
        TypeError: ``A`` or ``B`` is not a sequence of matrices.
        QsicError: an array whose shape is not ``(N, 4, 4)``, lengths that differ, or
            ``threads`` or ``budget`` out of range or not an integer; nothing is computed then.
    """
    threads = _thread_count(threads)
    budget = _budget(budget)
    floats = _inputs.check_floats(floats)
    ka, da, na = _inputs.batch_side("A", A, floats)
    kb, db, nb = _inputs.batch_side("B", B, floats)
    if na != nb:
        raise QsicError(f"A holds {na} matrices and B {nb}: the lengths must be equal")
    cols = _qsic.classify_many(
        ka, da, kb, db, affine=affine, chart=chart, threads=threads, budget=budget
    )
    out: Dict[str, np.ndarray] = {}
    for key in FIELDS:
        if key == "case":
            out[key] = np.frombuffer(cols["case"], dtype=np.int8).copy()
        else:
            out[key] = _objects(cols[key])
    if affine:
        out["affine"] = _objects(
            [None if t is None else json.loads(t) for t in cols["affine"]]
        )
    out["error"] = _objects(cols["error"])
    return out


def _objects(values: List[Any]) -> np.ndarray:
    return np.fromiter(values, dtype=object, count=len(values))


def param(
    a: QuadricLike,
    b: QuadricLike,
    *,
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Dict[str, Any]:
    """The exact curve: the JSON object of ``qsic param --json A B`` (README, "qsic param"):
    the classification's fields, ``numbers``, every component's parameterization as strings
    that sympy reads, and the real singular points; with ``affine`` (the default) each real
    conic's ``affine`` data (type, centre or vertex, axes) and the pair's ``affine`` object in
    the chart ``chart = 0`` at infinity (default ``w``), as ``--chart``; ``affine=False`` is
    ``--projective``. Each real line, conic and point also has its ``frame``, what a CAD
    kernel takes (README, "Frames"): a conic's location (centre or vertex), normal, X and Y
    directions and radius, semi-axes or focal length, as OpenCASCADE's ``gp_Ax2`` and
    ``gp_Circ``/``gp_Elips``/``gp_Hypr``/``gp_Parab``; a line's point nearest the origin (a point of it over a field larger than ℚ) and
    direction (``gp_Lin``); exact strings, decimals under ``"approx"``. ``floats`` as for
    :func:`classify`. ``budget``: the work units the call may spend (as :func:`classify`).

    >>> f = param("x^2+y^2+z^2-25", "z-3")["components"][0]["frame"]
    >>> (f["type"], f["location"], f["radius"]["exact"], f["approx"]["normal"])
    ('circle', ['0', '0', '3'], '4', [0.0, 0.0, 1.0])

    Raises:
        QsicError: a bad quadric, ``not yet: …`` for a class whose curve is not built, or
            ``over the work budget: …``.
    """
    floats = _inputs.check_floats(floats)
    return json.loads(
        _qsic.param(
            _side_native("A", a, floats),
            _side_native("B", b, floats),
            affine=affine,
            chart=chart,
            budget=_budget(budget),
        )
    )


def sample(
    a: QuadricLike,
    b: QuadricLike,
    *,
    points: int = 64,
    tolerance: Optional[float] = None,
    chart: Optional[str] = None,
    affine: bool = True,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Dict[str, Any]:
    """Real points on every real piece of the curve: the JSON object of ``qsic sample``, with
    every polyline a NumPy array.

    Each entry of ``components`` has ``branches`` (a list of ``(n, 4)`` float arrays of unit
    vectors ``[x, y, z, w]``) and ``affine`` with ``branches`` (``(n, 3)`` arrays in the chart
    ``chart = 0`` at infinity, default ``w``) and ``points_at_infinity`` (a ``(k, 4)`` array).
    At least ``points`` points per piece; with ``tolerance``, chords within it in the chart.
    ``floats`` and ``budget`` (the work units the call may spend) as for :func:`classify`.

    Raises:
        QsicError: as :func:`param`, and for bad options.
    """
    floats = _inputs.check_floats(floats)
    out = json.loads(
        _qsic.sample(
            _side_native("A", a, floats),
            _side_native("B", b, floats),
            points=points,
            tolerance=tolerance,
            chart=chart,
            affine=affine,
            budget=_budget(budget),
        )
    )
    for piece in out["components"]:
        piece["branches"] = [np.array(br, dtype=float).reshape(-1, 4) for br in piece["branches"]]
        aff = piece["affine"]
        aff["branches"] = [np.array(br, dtype=float).reshape(-1, 3) for br in aff["branches"]]
        aff["points_at_infinity"] = np.array(aff["points_at_infinity"], dtype=float).reshape(-1, 4)
    return out


def nurbs(
    a: QuadricLike,
    b: QuadricLike,
    *,
    bounds: Optional[Sequence[Any]] = None,
    step: bool = False,
    budget: Optional[int] = None,
    floats: str = "binary",
    tolerance: Optional[float] = None,
) -> Any:
    """Every real piece of the curve as a NURBS curve: the JSON object of ``qsic nurbs --json
    A B`` (README, "qsic nurbs") — ``bounds`` (the box), ``curves`` (degree, knots and
    multiplicities, control points and weights as exact strings, their decimals under
    ``"approx"``, ``exact``, ``bound``, ``closed``, ``clipped``, ``piece``) and ``left`` (the
    pieces not given, and why); with ``step=True`` the STEP text of ``--format step``
    instead (a ``str``). ``bounds``: the box unbounded pieces are clipped to, six exact
    numbers ``(x0, y0, z0, x1, y1, z1)`` (int, ``Fraction``, str), as ``--box``. ``floats``
    as for :func:`classify`. ``tolerance``: the distance bound of the approximated quartic
    branches to both surfaces, as ``--tolerance`` (default ``1e-9`` of each branch's size).

    >>> n = nurbs("x^2+y^2+z^2-4", "x^2+y^2-2*x")  # Viviani: two loops through the node
    >>> [(c["degree"], c["exact"], c["multiplicities"][0]) for c in n["curves"]]
    [(4, True, 5), (4, True, 5)]

    Raises:
        QsicError: a bad quadric or box, ``not yet: …``, or ``over the work budget: …``.
    """
    floats = _inputs.check_floats(floats)
    box = None
    if bounds is not None:
        values = list(bounds)
        if len(values) != 6:
            raise QsicError(f"bounds: six numbers x0, y0, z0, x1, y1, z1 expected, got {len(values)}")
        box = ",".join(str(v) for v in values)
    out = _qsic.nurbs(
        _side_native("A", a, floats),
        _side_native("B", b, floats),
        bounds=box,
        step=step,
        budget=_budget(budget),
        tolerance=None if tolerance is None else float(tolerance),
    )
    return out if step else json.loads(out)


MovingLike = Union[str, Sequence[Sequence[Any]], np.ndarray, Dict[str, Any]]


def _moving(name: str, m: Any) -> List[str]:
    if isinstance(m, str):
        return [m]
    if isinstance(m, dict):
        # a quadric under a rigid motion, read as the CLI reads the JSON object form
        try:
            return [json.dumps(m, default=_json_scalar)]
        except (TypeError, ValueError) as e:
            raise QsicError(f"{name}: {e}") from None
    try:
        return _inputs.matrix_texts(m)
    except QsicError as e:
        raise QsicError(f"{name}: {e}") from None


def _json_scalar(v: Any) -> Any:
    """A number of a rigid motion that JSON does not write itself (a Fraction, a Decimal, a
    NumPy scalar), as its exact text."""
    if isinstance(v, np.ndarray):
        return v.tolist()
    return _inputs.number_text(v, "a rigid motion entry")


def _range(r: Optional[Tuple[Any, Any]]) -> Tuple[Optional[str], Optional[str]]:
    if r is None:
        return None, None
    t0, t1 = r
    return _range_end(t0, "range start"), _range_end(t1, "range end")


def _range_end(t: Any, name: str) -> Optional[str]:
    """An end of a time range: ``None``, a number, or an infinite float or ``Decimal`` (an
    open side, ``-oo`` / ``+oo`` as the CLI writes it; NaN is an error)."""
    if t is None:
        return None
    if isinstance(t, (float, np.floating, Decimal)) and not isinstance(t, bool):
        if t == t and abs(t) == float("inf"):  # not NaN
            return "+oo" if t > 0 else "-oo"
    return _inputs.number_text(t, name)


def motion(
    a: MovingLike,
    b: MovingLike,
    range: Optional[Tuple[Any, Any]] = None,
    budget: Optional[int] = None,
) -> Dict[str, Any]:
    """The instants where the type of the intersection of moving quadrics ``A(t)``, ``B(t)``
    changes, and the type on every interval and at every instant: the JSON object of
    ``qsic motion --json`` (README, "Moving quadrics").

    ``a``, ``b``: a polynomial string in ``x, y, z, w`` whose coefficients are rational
    functions of ``t`` (``"(x - t)^2 + y^2 + z^2 - 1"``), a 4×4 array of numbers and
    strings of rational functions of ``t``, or a quadric under a rigid motion, a dict as the
    CLI's JSON object form: ``{"quadric": "x^2/4 + y^2 + z^2 - 1", "rotate": {"axis": [0, 0,
    1]}, "translate": [0, 0, "t"]}`` (``"rotate"``: ``"axis"`` for the Cayley rotation
    ``tan(θ/2) = t·|axis|``, or ``"quaternion"`` ``[q0, q1, q2, q3]`` polynomials in ``t``;
    ``"center"`` a point of the axis; README, "Rigid motions"). ``range = (t0, t1)``: only
    ``t`` in ``[t0, t1]``, None for an open side. ``budget``: the work units the call may
    spend (:data:`DEFAULT_BUDGET` by default; README, "Work budget").

    Raises:
        QsicError: the reader's or the analysis' message, a budget that is not a positive
            integer, or ``over the work budget: …``.
    """
    t0, t1 = _range(range)
    units = _budget(budget)
    return json.loads(_qsic.motion(_moving("A", a), _moving("B", b), t0, t1, budget=units))


def first_contact(
    a: MovingLike,
    b: MovingLike,
    range: Optional[Tuple[Any, Any]] = None,
    budget: Optional[int] = None,
    first_only: bool = False,
) -> Dict[str, Any]:
    """The first ``t`` in ``range`` where moving quadrics have a real common point, and the
    relation of the solids along the motion where both are ellipsoids: the JSON object of
    ``qsic contact --json`` (``range``, ``first_contact``: None, ``"-oo"``, ``"p/q"`` or
    ``{"poly", "interval", "approx"}``, ``contact``: the common points there, exact and in
    decimals, and ``at_start`` when they already meet at the range's start; ``solids``: the
    relation on the range only). ``a``, ``b``, ``range = (t0, t1)`` and ``budget`` as for
    :func:`motion` (rigid motions as dicts). ``first_only=True``: the instant alone (``range``
    and ``first_contact``, as ``qsic contact --first-only``), without the points and the
    solids — the call for a loop over many pairs and time steps.

    Raises:
        QsicError: the reader's or the analysis' message, a bad budget, or ``over the work
            budget: …``.
    """
    t0, t1 = _range(range)
    units = _budget(budget)
    return json.loads(
        _qsic.first_contact(
            _moving("A", a), _moving("B", b), t0, t1, budget=units, first_only=first_only
        )
    )
