// SurfaceMaps engine: how the process's allocator treats memory it frees.
#pragma once

namespace surfacemaps
{

/// Makes the whole process keep the memory it frees for its next allocations
/// instead of handing it back to the operating system, for programs that run
/// one map (or a few) and exit, such as the `surfacemap` command.
///
/// Why: every Newton step of a map allocates and frees buffers the size of the
/// sparse Hessian and of its Cholesky factor (CHOLMOD's numeric factor and
/// transposes, the objective's assembly tables: megabytes each; their
/// pattern changes with every remeshing). glibc serves blocks this large with
/// fresh mappings and returns freed memory above 128 KiB at the top of its
/// heaps to the system, so each step touches fresh pages again: thousands of
/// page faults per step, each a trip into the kernel. This raises glibc's
/// mapping threshold to its maximum (32 MiB on 64-bit) and its trim threshold
/// to 1 GiB. The cost: the process keeps up to 1 GiB of freed memory at the
/// top of its heaps until it exits.
///
/// Process-wide and irreversible, so the library never calls it itself: an
/// application decides. glibc only; returns false and changes nothing with
/// another C library, or when GLIBC_TUNABLES sets any glibc.malloc tunable
/// (the user's own settings win). Returns true when both thresholds are set.
bool keepFreedMemoryForReuse();

} // namespace surfacemaps
