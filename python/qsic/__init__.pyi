"""Exact classification of the intersection curve of two quadric surfaces (type stubs)."""

from typing import Any, Dict, Optional, Sequence, Tuple, Union

import numpy as np

from ._qsic import QsicError as QsicError

FIELDS: Tuple[str, ...]
MAX_THREADS: int
DEFAULT_BUDGET: int

Number = Union[int, float, str, Any]  # also Fraction, Decimal, NumPy scalars
QuadricLike = Union["Quadric", str, Sequence[Sequence[Number]], np.ndarray]
MovingLike = Union[str, Sequence[Sequence[Number]], np.ndarray, Dict[str, Any]]
Range = Optional[Tuple[Optional[Number], Optional[Number]]]

class Quadric:
    """A quadric surface XᵀAX = 0 from a polynomial string or a 4×4 array, read exactly."""

    def __init__(self, source: QuadricLike, *, floats: str = "binary") -> None: ...
    @property
    def matrix(self) -> np.ndarray: ...
    @property
    def polynomial(self) -> str: ...
    @property
    def is_plane(self) -> bool: ...
    def __eq__(self, other: object) -> bool: ...
    @classmethod
    def sphere(cls, center: Sequence[Number], r2: Number, *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def ellipsoid(cls, center: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def cylinder(cls, point: Sequence[Number], direction: Sequence[Number], r2: Number, *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def elliptic_cylinder(cls, axis: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def cone(cls, apex: Sequence[Number], direction: Sequence[Number], cos2: Number, *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def elliptic_cone(cls, apex: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def elliptic_paraboloid(cls, vertex: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def hyperbolic_paraboloid(cls, vertex: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def hyperboloid_one_sheet(cls, center: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def hyperboloid_two_sheets(cls, center: Sequence[Number], semi_axes2: Sequence[Number], *, floats: str = "binary") -> Quadric: ...
    @classmethod
    def plane_pair(cls, n1: Sequence[Number], d1: Number, n2: Sequence[Number], d2: Number, *, floats: str = "binary") -> Quadric: ...

class Classification:
    """The JSON result object of `qsic classify`; str() is the text report."""

    @property
    def pencil(self) -> str: ...
    @property
    def case(self) -> Optional[int]: ...
    @property
    def segre(self) -> Optional[str]: ...
    @property
    def signature(self) -> Optional[str]: ...
    @property
    def index_sequence(self) -> Optional[str]: ...
    @property
    def complex_type(self) -> Optional[str]: ...
    @property
    def real_type(self) -> Optional[str]: ...
    @property
    def components(self) -> list: ...
    @property
    def singular_points(self) -> list: ...
    @property
    def description(self) -> Optional[str]: ...
    @property
    def affine(self) -> Optional[Dict[str, Any]]: ...
    def to_dict(self) -> Dict[str, Any]: ...

def classify(
    a: QuadricLike,
    b: QuadricLike,
    *,
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Classification: ...
def classify_many(
    A: Any,
    B: Any,
    *,
    affine: bool = False,
    chart: Optional[str] = None,
    threads: Optional[int] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Dict[str, np.ndarray]: ...
def param(
    a: QuadricLike,
    b: QuadricLike,
    *,
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
    floats: str = "binary",
) -> Dict[str, Any]: ...
def nurbs(
    a: QuadricLike,
    b: QuadricLike,
    *,
    bounds: Optional[Sequence[Any]] = None,
    step: bool = False,
    budget: Optional[int] = None,
    floats: str = "binary",
    tolerance: Optional[float] = None,
) -> Any: ...
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
) -> Dict[str, Any]: ...
def motion(
    a: MovingLike, b: MovingLike, range: Range = None, budget: Optional[int] = None
) -> Dict[str, Any]: ...
def first_contact(
    a: MovingLike,
    b: MovingLike,
    range: Range = None,
    budget: Optional[int] = None,
    first_only: bool = False,
) -> Dict[str, Any]: ...
