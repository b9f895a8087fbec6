"""The errors of the vision path (images that cannot be read or have the wrong shape or type).

>>> from pgsym.errors import PgsymError
>>> issubclass(ImageError, PgsymError) and issubclass(ImageError, ValueError)
True
"""

from __future__ import annotations

from ..errors import PgsymError

__all__ = ["ImageError"]


class ImageError(PgsymError, ValueError):
    """An image cannot be read, or has the wrong shape or type for the operation."""
