# Type hints of the package mcmd (its public API: mcmd/__init__.py).
import os
from typing import Any, Callable, Iterable, Mapping, Optional

import numpy as np
import numpy.typing as npt

__version__: str
__all__: list[str]

Progress = Callable[[float], Optional[bool]]

class Error(RuntimeError): ...
class Cancelled(Error): ...

def fill(
    array: Any,  # (rows, columns) or (bands, rows, columns): ndarray, masked array or xarray.DataArray
    mask: npt.ArrayLike | None = ...,
    nodata: int | float | Iterable[int | float | None] | None = ...,
    *,
    method: str = ...,
    rs: float | str = ...,
    seed: int = ...,
    max_distance: float = ...,
    threads: int | None = ...,
    progress: Progress | None = ...,
    **options: Any,
) -> Any: ...  # the kind of `array` (ndarray, masked array, DataArray), its dtype
def fill_file(
    src: str | os.PathLike[str],
    dst: str | os.PathLike[str] | None = ...,
    *,
    bands: int | Iterable[int] | None = ...,
    mask: str | os.PathLike[str] | None = ...,
    nomask: bool = ...,
    format: str | None = ...,
    creation_options: Mapping[str, Any] | Iterable[str] | None = ...,
    progress: Progress | None = ...,
    **options: Any,
) -> str: ...
