"""The native half of `qsic` (PyO3). Use the functions of `qsic` itself: they accept
NumPy arrays and Python numbers and turn them into what these take."""

from typing import Dict, List, Optional, Tuple, Union

MAX_THREADS: int
DEFAULT_BUDGET: int
MAX_NUMBER_DIGITS: int

class QsicError(ValueError):
    """Bad input: the library's message."""

class NativeQuadric:
    def polynomial(self) -> str: ...
    def entries(self) -> List[str]: ...
    def is_plane(self) -> bool: ...
    def equals(self, other: NativeQuadric) -> bool: ...

def quadric_from_text(text: str) -> Optional[NativeQuadric]: ...
def quadric_from_entries(texts: List[str]) -> Optional[NativeQuadric]: ...
def quadric_from_machine(kind: str, data: bytes) -> Optional[NativeQuadric]: ...
def quadric_from_shape(name: str, args: List[List[str]]) -> NativeQuadric: ...
def classify(
    a: Optional[NativeQuadric],
    b: Optional[NativeQuadric],
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
) -> Tuple[str, str]: ...
def classify_many(
    a_kind: str,
    a: Union[bytes, Tuple[List[str], Dict[int, str]]],
    b_kind: str,
    b: Union[bytes, Tuple[List[str], Dict[int, str]]],
    affine: bool = False,
    chart: Optional[str] = None,
    threads: Optional[int] = None,
    budget: Optional[int] = None,
) -> Dict[str, Union[bytes, list]]: ...
def param(
    a: Optional[NativeQuadric],
    b: Optional[NativeQuadric],
    affine: bool = True,
    chart: Optional[str] = None,
    budget: Optional[int] = None,
) -> str: ...
def nurbs(
    a: Optional[NativeQuadric],
    b: Optional[NativeQuadric],
    bounds: Optional[str] = None,
    step: bool = False,
    budget: Optional[int] = None,
    tolerance: Optional[float] = None,
) -> str: ...
def sample(
    a: Optional[NativeQuadric],
    b: Optional[NativeQuadric],
    points: int = 64,
    tolerance: Optional[float] = None,
    chart: Optional[str] = None,
    affine: bool = True,
    budget: Optional[int] = None,
) -> str: ...
def motion(a: List[str], b: List[str], t0: Optional[str] = None, t1: Optional[str] = None) -> str: ...
def first_contact(
    a: List[str],
    b: List[str],
    t0: Optional[str] = None,
    t1: Optional[str] = None,
    budget: Optional[int] = None,
    first_only: bool = False,
) -> str: ...
