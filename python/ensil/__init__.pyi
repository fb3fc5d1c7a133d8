# Type hints of the `ensil` package (python/ensil/__init__.py and the extension ensil._ensil).
import os
from typing import Any, Mapping, Optional, Sequence, Union

import numpy as np
import numpy.typing as npt

from ._ensil import (
    ArgumentError as ArgumentError,
    DataWarning as DataWarning,
    Ensemble as Ensemble,
    Error as Error,
    Mesh as Mesh,
    PreprocessResult as PreprocessResult,
    Section as Section,
    ProgressCallback,
    Session as Session,
    SettingValue,
    Settings as Settings,
    TimeStep as TimeStep,
    __version__ as __version__,
    demo as demo,
)

PathLike = Union[str, os.PathLike[str]]
Axis = Union[npt.ArrayLike, tuple[npt.ArrayLike, str]]

def open(paths: Union[PathLike, Sequence[PathLike]], var: Optional[str] = None,
         member_dim: Optional[str] = None, time_index: int = 0, levels: Optional[str] = None,
         bbox: Union[tuple[float, float, float, float], Sequence[float], str, None] = None,
         progress: ProgressCallback = None) -> Ensemble: ...
def from_numpy(values: Any, axes: Union[Mapping[str, Axis], Sequence[npt.ArrayLike], None] = None,
               units: Optional[str] = None, names: Optional[Sequence[str]] = None,
               variable: Optional[str] = None,
               grid_mapping: Optional[Mapping[str, Any]] = None) -> Ensemble: ...
def from_xarray(data: Any, var: Optional[str] = None, member_dim: Optional[str] = None,
                time_index: int = 0) -> Ensemble: ...

class Image(np.ndarray[Any, np.dtype[np.uint8]]):
    session: Optional[Session]
    facts: dict[str, Any]
    def __new__(cls, rgba: npt.ArrayLike, session: Optional[Session] = None,
                facts: Optional[dict[str, Any]] = None) -> Image: ...
    def _repr_png_(self) -> bytes: ...
    def save(self, path: PathLike) -> None: ...

def render(target: Union[Ensemble, Session, PathLike], iso: Optional[float] = None,
           size: tuple[int, int] = (1600, 1000), mode: Optional[str] = None,
           view: Optional[str] = None, cache: bool = True,
           **settings: SettingValue) -> Image: ...
