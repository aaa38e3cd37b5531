// SurfaceMaps engine: BlasThreadGuard, which keeps BLAS on one thread while a
// CHOLMOD factorisation or solve runs and gives the caller back its OpenMP
// thread count afterwards.
#pragma once

namespace surfacemaps
{

// CHOLMOD's supernodal factorisation calls BLAS on many small dense blocks.
// A multithreaded OpenBLAS slows that down by an order of magnitude (its
// threads fight the engine's OpenMP threads over 2 cores), so BLAS runs on
// one thread while any factorisation runs and is restored when the last one
// ends. Neither CHOLMOD nor Eigen sets the BLAS thread count, and OpenBLAS
// has no per-call setting, hence this guard. The thread count is global:
// concurrent solvers (several embeddings at once) share one count of active
// guards, or one of them would restore the old count while another
// factorises, with results that change from run to run. Looked up at run
// time: with another BLAS there is nothing to do. OpenBLAS' OpenMP build sets
// the calling thread's OpenMP thread count in openblas_set_num_threads, so
// each guard also restores the count its own thread had (otherwise
// omp_set_num_threads(1) or a per-rank thread count would be overridden by
// OpenBLAS' count after the first solve).
class BlasThreadGuard
{
public:
  BlasThreadGuard();
  ~BlasThreadGuard();
  BlasThreadGuard(const BlasThreadGuard&) = delete;
  BlasThreadGuard& operator=(const BlasThreadGuard&) = delete;

private:
  const int OpenMPThreads;
};

} // namespace surfacemaps
