# Type stubs of the sweetspot module (python/module.cpp); docs/python.md.
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

__version__: str

Design = Union[Mapping[str, Any], str, os.PathLike[str]]
Fidelity = Optional[str]  # "rigid", "modal", "response", "collision", "auto"; None: the design's own

class InputError(ValueError):
    """Bad input (exit status 2): str() is 'SOURCE: PATH: DETAIL', the command line's words."""
    source: str
    path: str
    detail: str
    expected: str
    value: Optional[str]

class ModelRefusal(RuntimeError):
    """The model cannot answer a design whose inputs are in range (exit status 3)."""
    source: str
    path: str
    detail: str
    expected: str
    value: Optional[str]

def evaluate(design: Design, fidelity: Fidelity = None, tol: float = 1e-6) -> dict[str, Any]:
    """Every output of one design: the dict `sweetspot evaluate --format json` prints (SI units)."""

def evaluate_many(
    base: Design,
    columns: Mapping[str, npt.ArrayLike],
    fidelity: Fidelity = None,
    threads: Optional[int] = None,
    tol: float = 1e-6,
    outputs: Optional[Sequence[str]] = None,
    out: Optional[Mapping[str, npt.NDArray[np.float64]]] = None,
) -> dict[str, npt.NDArray[Any]]:
    """Rows of designs from columns keyed by dotted field names; one float64 array per output
    (written into out's array where given), 'ok' (bool) and 'error' (read-only object array,
    '' for a row that evaluated)."""

def modes(design: Design, count: int = 3, tol: float = 1e-6, method: str = "exact") -> dict[str, Any]:
    """The vibration modes free and hand-held (`sweetspot modes --format json`) and their shapes."""

def collide(design: Design, tol: float = 1e-6) -> dict[str, Any]:
    """The solved collision of ball, strings and frame, with its force history (s, N)."""

def string_bed_map(
    design: Design,
    columns: int = 50,
    rows: int = 50,
    fidelity: Fidelity = None,
    threads: Optional[int] = 1,
) -> dict[str, Any]:
    """Power, shock and feel over the string bed as 2-D arrays (rows x columns)."""

def optimize(study: Design, threads: Optional[int] = None) -> dict[str, Any]:
    """A study's optimisation: best design, objective, constraints, histories (NumPy arrays)."""

def tune(
    design: Design,
    target: Union[Mapping[str, float], str, None] = None,
    *,
    places: Union[str, Sequence[str]],
    like: Optional[Design] = None,
    strip_g: float = 1.0,
    tol: float = 1e-6,
) -> dict[str, Any]:
    """The least lead, and where (places: clock hours, 3/9, throat, grip, handle or butt), that reaches
    target specs (mass_g, balance_cm or balance_pts_hl, swingweight_kg_cm2, twistweight_kg_cm2): the lead per
    place, the specs before and reached (SI), misses, the tuned design, the report."""

def outputs() -> list[dict[str, Any]]:
    """Every output of evaluate(): name, SI unit, description, when it is None."""
