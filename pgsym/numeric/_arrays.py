"""Shared machinery of the numeric kernels: input checks and a cache-blocked row loop.

Every kernel works on float64 arrays whose component axis (``axis``, the last one by
default) holds the homogeneous coordinates; all other axes broadcast. The loop below
walks over the rows in blocks of :data:`CHUNK` so that the few scratch buffers a formula
needs stay in the processor cache: each block is read from memory once and written once,
which keeps a kernel close to the memory-bandwidth floor instead of paying one memory pass
per arithmetic operation.

Every block's output is checked for NaN and infinity while it is still in the cache: one
sum per block, and a full test only when that sum is not finite (see the policy in
:mod:`pgsym.numeric`).

Only NumPy is imported here (and by every module of :mod:`pgsym.numeric` except the
conversions, which import the exact core inside their functions).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

from ..errors import DimensionError, NonFiniteError, NonNumericError, OptionError

__all__ = [
    "CHUNK",
    "COMPLEX_KERNELS",
    "DEGENERATE",
    "NONFINITE",
    "ZERO_OR_DEGENERATE",
    "OptionError",
    "as_float_array",
    "as_numeric_arrays",
    "block_finite",
    "construction",
    "degenerate_result",
    "finite_and_no_zero_row",
    "no_zero_row",
    "nonfinite_result",
    "rowwise",
]

CHUNK = 8192
"""Rows per block: a few blocks of 8192 float64 triples fit in a typical L2 cache."""

NONFINITE = ("raise", "mask")
"""The values of every kernel's ``nonfinite=`` option: raise NonFiniteError, or return ``(values, finite)``."""

DEGENERATE = ("raise", "mask")
"""The values of a construction's ``degenerate=`` option: raise the named error, or return ``(values, ok)``."""

ZERO_OR_DEGENERATE = ("zero", *DEGENERATE)

COMPLEX_KERNELS = ("cross", "join", "meet", "incident", "is_zero_vector", "bracket", "harmonic_conjugate")
"""The kernels that accept complex arrays (the circular points I, J and other complex points): their formulas
are polynomial, without conjugation, so they hold over ℂ as they do over ℝ. Every other kernel measures
(distances, angles, orientations) or decides by a real tolerance, and refuses complex input by name."""
"""The ``degenerate=`` values of the joins and meets, whose default ``"zero"`` returns the zero vector."""

Kernel = Callable[[list[np.ndarray], np.ndarray, list[np.ndarray]], None]


def block_finite(block: np.ndarray) -> bool:
    """False when ``block`` may hold NaN or infinity: one BLAS dot product of the block with itself.

    NaN and ±inf propagate into ``Σ x²``, so a finite sum proves every entry finite; an
    infinite sum from squares beyond 1e308 is a false alarm that the caller's full test clears.
    The dot product runs at several times the speed of ``np.sum``, which matters because it is
    paid once per block of every kernel call (run it while the block is in cache).

    >>> block_finite(np.ones((4, 3))), block_finite(np.array([[1.0, np.nan]]).T)
    (True, False)
    """
    dot = np.vdot if block.dtype.kind == "c" else np.dot  # Σ |x|² for complex blocks
    if block.flags.c_contiguous:
        flat = block.reshape(-1)
        return math.isfinite(abs(dot(flat, flat)))
    for i in range(block.shape[-1]):  # component-major layout: each component is contiguous
        c = block[..., i]
        if not math.isfinite(abs(dot(c, c))):
            return False
    return True


_WEIGHTS = np.sqrt(np.array([2.0, 3, 5, 7, 11, 13]))  # rationally independent: only a zero row can miss all


def no_zero_row(rows: np.ndarray) -> bool:
    """True when no row (last axis) of ``rows`` is the zero vector; False may be a false alarm.

    One matrix–vector product with the weights ``√2, √3, √5, …``: a zero row gives 0, a nonzero row gives 0
    only by accident (the weights are rationally independent, so never for integer rows) or by underflow,
    and then the caller's exact test decides. Several times faster than ``rows.any(axis=-1)``.

    >>> no_zero_row(np.array([[1.0, -1, 0], [0, 0, 2]])), no_zero_row(np.array([[1.0, 2], [0, 0]]))
    (True, False)
    """
    if rows.size == 0:
        return True
    with np.errstate(under="ignore", over="ignore", invalid="ignore"):
        return bool(np.dot(rows, _WEIGHTS[: rows.shape[-1]]).all())


def finite_and_no_zero_row(rows: np.ndarray) -> bool:
    """True when every entry of ``rows`` is finite and no row is zero; False may be a false alarm.

    Both from one matrix–vector product ``v = rows · (√2, √3, …)``: NaN and ±inf in a row make its entry of
    ``v`` NaN or infinite (the weights are nonzero), a zero row makes it 0. Then a sum of ``v`` (NaN and inf
    propagate; an overflow is a false alarm) and ``v.all()`` decide, over a vector ``k`` times shorter.

    >>> finite_and_no_zero_row(np.array([[1.0, 2], [3, 4]])), finite_and_no_zero_row(np.array([[1.0, np.inf]]))
    (True, False)
    """
    if rows.size == 0:
        return True
    with np.errstate(under="ignore", over="ignore", invalid="ignore"):
        v = np.dot(rows, _WEIGHTS[: rows.shape[-1]])
        return math.isfinite(np.sum(v)) and bool(v.all())


def check_option(value: str, allowed: Sequence[str], name: str, function: str) -> None:
    """Raise :class:`OptionError` unless ``value`` is one of ``allowed``.

    >>> check_option("raise", ("raise", "mask"), "ideal", "dehomogenize")
    """
    if value not in allowed:
        choices = ", ".join(repr(a) for a in allowed)
        raise OptionError(f"{function}: {name}={value!r} is not an option; use one of {choices}")


def nonfinite_result(
    result: np.ndarray, finite: np.ndarray, nonfinite: str, function: str, inputs: Sequence[np.ndarray] = ()
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Apply the policy to a result whose rows are ``finite`` (the batch shape): raise, or NaN-fill and mask.

    ``result`` has the batch shape, or the batch shape plus a last component axis. ``inputs`` (broadcast
    against the batch) tell a non-finite input from an overflow in the message.

    >>> nonfinite_result(np.array([[1.0, 2], [np.inf, 0]]), np.array([True, False]), "mask", "f")
    (array([[ 1.,  2.],
           [nan, nan]]), array([ True, False]))
    """
    if finite.all():
        return (result, np.asarray(finite)) if nonfinite == "mask" else result
    if nonfinite == "mask":
        result[~finite] = np.nan
        return result, np.asarray(finite)
    first = tuple(int(i) for i in np.argwhere(~finite)[0]) if finite.ndim else ()
    cause = "overflows float64 (its entries are too large to multiply)"
    for a in inputs:
        row = np.broadcast_to(a, (*finite.shape, a.shape[-1]))[first]
        if not np.isfinite(row).all():
            cause = f"comes from an input holding NaN or infinity: {row.tolist()}"
            break
    raise NonFiniteError(
        f"{function}: {int((~finite).sum())} of the {finite.size} results are NaN or infinite; the first, at index "
        f"{first}, {cause}. The numeric path computes only with finite numbers: repair the input, rescale it, or "
        "pass nonfinite='mask' to get the finite results with a mask"
    )


def as_float_array(x: Any, name: str, function: str) -> np.ndarray:
    """``x`` as a float64 ndarray (no copy when it already is one), or :class:`NonNumericError`.

    >>> as_float_array([1, 2, 3], "p", "join").dtype
    dtype('float64')
    """
    if isinstance(x, np.ndarray) and x.dtype == np.float64:
        return x
    try:
        a = np.asarray(x)
        complex_input = a.dtype.kind == "c"
        if not complex_input:
            return np.asarray(a, dtype=np.float64)
    except (TypeError, ValueError) as err:
        raise NonNumericError(
            f"{function}: {name} must be an array of real numbers, got {type(x).__name__}; "
            "exact pgsym objects convert with pgsym.numeric.to_array"
        ) from err
    # casting would drop the imaginary parts (NumPy only warns): refuse by name
    raise NonNumericError(
        f"{function}: {name} holds complex numbers, and {function} works on real coordinates only; "
        f"the kernels that take complex arrays are {', '.join(COMPLEX_KERNELS)}"
    )


def _is_complex(x: Any) -> bool:
    """True for complex input; False for anything else, including what as_float_array will refuse by name."""
    try:
        return bool(np.iscomplexobj(x))
    except (TypeError, ValueError):
        return False


def as_numeric_arrays(inputs: Sequence[tuple[Any, str]], function: str, complex_ok: bool) -> list[np.ndarray]:
    """The inputs as float64 arrays, or all as complex128 when ``complex_ok`` and one of them is complex.

    >>> [a.dtype.name for a in as_numeric_arrays([([1, 2], "p"), ([1j, 0], "q")], "join", True)]
    ['complex128', 'complex128']
    """
    if complex_ok and any(_is_complex(x) for x, _ in inputs):
        out = []
        for x, name in inputs:
            try:
                out.append(np.asarray(x, dtype=np.complex128))
            except (TypeError, ValueError) as err:
                raise NonNumericError(
                    f"{function}: {name} must be an array of real or complex numbers, got {type(x).__name__}"
                ) from err
        return out
    return [as_float_array(x, name, function) for x, name in inputs]


def _move(a: np.ndarray, k: int, axis: int, name: str, function: str) -> np.ndarray:
    if a.ndim == 0 or not -a.ndim <= axis < a.ndim or a.shape[axis] != k:
        raise DimensionError(
            f"{function}: {name} must have {k} homogeneous coordinates along axis {axis}, got an array of "
            f"shape {a.shape}; pass axis=0 for a component-major ({k}, N) array"
        )
    return a if axis in (-1, a.ndim - 1) else np.moveaxis(a, axis, -1)


def _flat(a: np.ndarray, k: int | None) -> np.ndarray | None:
    """A (rows, k) or (rows,) view of ``a`` without copying, or None when that needs a copy."""
    try:
        return a.reshape((-1, k) if k is not None else (-1,), copy=False)
    except ValueError:
        return None


def rowwise(
    kernel: Kernel,
    function: str,
    inputs: Sequence[tuple[Any, int, str]],
    k_out: int | None,
    out: np.ndarray | None,
    axis: int,
    n_scratch: int,
    nonfinite: str = "raise",
    complex_ok: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Run ``kernel`` over broadcast rows of ``inputs`` block by block, writing into ``out``.

    ``inputs`` are ``(array, k, name)`` triples; ``k_out`` is the number of output
    components (None for one scalar per row). The kernel receives the input blocks
    (shape ``(n, k)``), the output block and ``n_scratch`` scratch vectors of length
    ``n``; it indexes components with ``x[..., i]``. Returns ``out`` (allocated when None,
    with its component axis at ``axis`` like the inputs). A NaN or infinite result (from a
    non-finite input, or an overflow) raises :class:`~pgsym.errors.NonFiniteError`; with
    ``nonfinite="mask"`` the rows holding one are set to NaN and ``(out, finite)`` is returned.

    >>> def add(ins, o, ws):
    ...     np.add(ins[0], ins[1], out=o)
    >>> rowwise(add, "add", [([1.0, 2.0], 2, "a"), ([[1.0, 1.0]] * 3, 2, "b")], 2, None, -1, 0)
    array([[2., 3.],
           [2., 3.],
           [2., 3.]])
    """
    check_option(nonfinite, NONFINITE, "nonfinite", function)
    numeric = as_numeric_arrays([(x, name) for x, _, name in inputs], function, complex_ok)
    arrays = [_move(a, k, axis, name, function) for a, (_, k, name) in zip(numeric, inputs, strict=True)]
    dtype = arrays[0].dtype if arrays else np.dtype(np.float64)
    batch = np.broadcast_shapes(*(a.shape[:-1] for a in arrays))
    full = batch if k_out is None else (*batch, k_out)
    if out is None:
        if k_out is None or axis in (-1, len(full) - 1):
            result = np.empty(full, dtype)
            o = result
        else:
            shape = list(batch)
            position = axis if axis >= 0 else len(full) + axis
            shape.insert(position, k_out)
            result = np.empty(shape, dtype)
            o = np.moveaxis(result, position, -1)
    else:
        if not isinstance(out, np.ndarray) or out.dtype != dtype or not out.flags.writeable:
            raise NonNumericError(f"{function}: out must be a writeable {dtype.name} ndarray, got {type(out).__name__}"
                                  + (f" of {out.dtype.name}" if isinstance(out, np.ndarray) else ""))
        result = out
        o = out if k_out is None else _move(out, k_out, axis, "out", function)
        if o.shape != full:
            raise DimensionError(
                f"{function}: out has shape {out.shape}, but the result has shape {full} (component axis {axis})"
            )
        if any(np.may_share_memory(o, a) for a in arrays):  # formulas read inputs after writing outputs
            tmp = rowwise(
                kernel,
                function,
                [(a, a.shape[-1], n) for a, (_, _, n) in zip(arrays, inputs, strict=True)],
                k_out,
                None,
                -1,
                n_scratch,
                nonfinite,
                complex_ok,
            )
            if nonfinite == "mask":
                tmp, finite = tmp
                np.copyto(o, tmp)
                return result, finite
            np.copyto(o, tmp)
            return result
    views = [np.broadcast_to(a, (*batch, a.shape[-1])) for a in arrays]
    if len(batch) == 0:
        views, o_rows = [v[None] for v in views], o[None]
    elif len(batch) == 1:
        o_rows = o
    else:
        flat = [_flat(v, v.shape[-1]) for v in views]
        o_rows = _flat(o, k_out)
        if o_rows is None or any(f is None for f in flat):  # strides do not allow a flat view: one block
            with np.errstate(over="ignore", invalid="ignore"):
                kernel(views, o, [np.empty(batch, dtype) for _ in range(n_scratch)])
            finite = np.isfinite(o) if k_out is None else np.isfinite(o).all(axis=-1)
            checked = nonfinite_result(o, finite, nonfinite, function, arrays)  # fills o's bad rows in mask mode
            return (result, checked[1]) if nonfinite == "mask" else result
        views = flat  # type: ignore[assignment]
    rows = o_rows.shape[0]
    if rows == 0:  # an empty batch: an empty result (and an empty mask)
        return (result, np.ones(batch, bool)) if nonfinite == "mask" else result
    block = min(CHUNK, rows)
    scratch = [np.empty(block, dtype) for _ in range(n_scratch)]
    suspect = []
    with np.errstate(over="ignore", invalid="ignore"):  # overflow and NaN are reported below, by name
        for start in range(0, rows, block):
            stop = min(start + block, rows)
            o_block = o_rows[start:stop]
            kernel([v[start:stop] for v in views], o_block, [w[: stop - start] for w in scratch])
            if not block_finite(o_block):
                suspect.append((start, stop))
    if not suspect and nonfinite == "raise":
        return result
    finite = np.ones(rows, bool)
    for start, stop in suspect:
        block_ok = np.isfinite(o_rows[start:stop])
        finite[start:stop] = block_ok if k_out is None else block_ok.all(axis=-1)
    if finite.all() and nonfinite == "raise":
        return result
    if nonfinite == "mask" and not finite.all():
        o_rows[~finite] = np.nan
    finite = finite.reshape(batch)
    if nonfinite == "mask":
        return result, finite
    return nonfinite_result(result, finite, nonfinite, function, arrays)


def degenerate_result(
    value: np.ndarray | tuple[np.ndarray, np.ndarray],
    degenerate: str,
    axis: int,
    function: str,
    error: type[Exception],
    what: str,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """Apply the degeneracy policy to a construction's ``value`` (an array, or ``(array, finite)``).

    A result that is the zero vector (every component exactly 0) is no projective object: with
    ``degenerate="raise"`` it raises ``error`` (naming how many rows and the first), with ``"mask"``
    its row is set to NaN and ``(values, ok)`` is returned, ``ok`` False there and where ``finite``
    was False. ``"zero"`` (accepted by the P² join and meet only) returns ``value`` unchanged.

    >>> degenerate_result(np.array([[1.0, 2], [0, 0]]), "mask", -1, "f", ValueError, "are zero")
    (array([[ 1.,  2.],
           [nan, nan]]), array([ True, False]))
    """
    if degenerate == "zero":
        return value
    result, finite = value if isinstance(value, tuple) else (value, None)
    components = np.moveaxis(result, axis, -1)
    if degenerate == "raise" and components.shape[-1] <= len(_WEIGHTS) and no_zero_row(components):
        return value  # no row is zero (a false alarm of the quick test goes on to the exact one below)
    zero = ~components.any(axis=-1)  # a NaN row (masked as non-finite) is not zero
    if degenerate == "raise":
        if zero.any():
            first = tuple(int(i) for i in np.argwhere(zero)[0]) if zero.ndim else ()
            raise error(
                f"{function}: {int(zero.sum())} of the {zero.size} inputs {what}, the first at index {first}; "
                "pass degenerate='mask' to get NaN rows there and a mask of the good ones"
            )
        return value
    if zero.any():
        components[zero] = np.nan
    ok = ~zero if finite is None else finite & ~zero
    return result, np.asarray(ok)


def construction(
    kernel: Kernel,
    function: str,
    inputs: Sequence[tuple[Any, int, str]],
    k_out: int,
    out: np.ndarray | None,
    axis: int,
    n_scratch: int,
    nonfinite: str,
    degenerate: str,
    error: type[Exception],
    what: str,
    complex_ok: bool = False,
) -> np.ndarray | tuple[np.ndarray, np.ndarray]:
    """:func:`rowwise`, then :func:`degenerate_result`: a construction under both policies of :mod:`pgsym.numeric`.

    >>> def add(ins, o, ws):
    ...     np.add(ins[0], ins[1], out=o)
    >>> construction(add, "add", [([1.0, -1], 2, "a"), ([[1.0, 1], [-1, 1]], 2, "b")], 2, None, -1, 0, "raise",
    ...              "mask", ValueError, "cancel")
    (array([[ 2.,  0.],
           [nan, nan]]), array([ True, False]))
    """
    if degenerate != "zero":  # the default of the joins costs no check
        check_option(degenerate, ZERO_OR_DEGENERATE, "degenerate", function)
    value = rowwise(kernel, function, inputs, k_out, out, axis, n_scratch, nonfinite, complex_ok)
    return degenerate_result(value, degenerate, axis, function, error, what)
