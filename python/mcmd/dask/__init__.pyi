# Type hints of mcmd.dask (its public API: mcmd/dask/__init__.py).
from typing import Any, Optional

__all__: list[str]

def fill(
    data: Any,
    mask: Any = ...,
    nodata: Any = ...,
    *,
    method: str = ...,
    rs: float | str = ...,
    seed: int = ...,
    max_distance: float = ...,
    chunks: Optional[int] = ...,
    **options: Any,
) -> Any: ...  # a dask array, or a DataArray for a DataArray
