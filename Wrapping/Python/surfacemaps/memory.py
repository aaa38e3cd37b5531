"""The process's allocator: keep the memory a map frees for its next Newton step (glibc's mallopt)."""

import ctypes
import os

# glibc's <malloc.h>
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3
# glibc refuses a mapping threshold above half its largest thread heap (32 MiB with 64-bit pointers).
_MAPPING_THRESHOLD = 32 * 1024 * 1024
_TRIM_THRESHOLD = 1024 * 1024 * 1024


def keep_freed_memory_for_reuse():
    """Make the whole process keep the memory it frees for its next allocations.

    Every Newton step of a map frees and reallocates buffers the size of the
    Hessian and its Cholesky factor; returned to the operating system, they
    come back as page faults on the next step. This raises glibc's mapping
    threshold to 32 MiB and its trim threshold to 1 GiB (as ``surfacemap``
    does in C++): up to 1 GiB of freed memory stays with the process until it
    exits. Process-wide and irreversible, so the package never calls it on
    import: a script that runs maps calls it once at its start
    (``python3 -m surfacemaps.population`` does).

    Returns True when both thresholds are set; False, changing nothing, with
    a C library other than glibc or when GLIBC_TUNABLES sets any
    glibc.malloc tunable (the user's own settings win).
    """
    if "glibc.malloc." in os.environ.get("GLIBC_TUNABLES", ""):
        return False
    try:
        libc = ctypes.CDLL(None)
        libc.gnu_get_libc_version  # glibc's own symbol: mallopt's constants are glibc's
        mallopt = libc.mallopt
    except (OSError, AttributeError):
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    return mallopt(_M_MMAP_THRESHOLD, _MAPPING_THRESHOLD) == 1 and mallopt(_M_TRIM_THRESHOLD, _TRIM_THRESHOLD) == 1
