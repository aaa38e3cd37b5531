// SurfaceMaps engine: the settings of a surface map.
#pragma once

#include "base/Log.h"
#include "map/MapPairs.h"

#include <functional>
#include <string>

namespace surfacemaps
{

/// Reported once per iteration of the schedule.
struct SurfaceMapProgress
{
  /// The running phase: "landmarks", "coarse", "fine", "refine" or "bound".
  std::string phase;
  int iteration = 0;
  /// Fraction of the whole schedule's iterations done (0..1).
  double fraction = 0.0;
  int vertices = 0;
  double energy = 0.0;
};

/// Every setting of computeSurfaceMap. The defaults written here are the
/// only ones: the settings table (MapSettings.h) gives each field its range,
/// its name in the filter, the command line and report.json, and its
/// documentation; everything else derives from the two. Lengths and errors
/// are in unit-area units (each input centred and scaled to unit area).
struct SurfaceMapOptions
{
  PairMode pairs = PairMode::Star;

  // Landmark phase (only with landmarks): barrier and landmark terms.
  int landmarkIterations = 100;
  double landmarkWeight = 1e6;
  double landmarkBarrierWeight = 1.0;
  double landmarkTolerance = 1e-4;
  bool relaxLandmarkPhase = true;
  bool keepLandmarks = true;

  // Coarse and fine phases: every term but the landmarks.
  int coarseIterations = 50;
  double coarseError = 1e-2;
  double coarseBarrierWeight = 1e-3;
  int fineIterations = 50;
  double targetError = 1e-3;
  double fineBarrierWeight = 1e-6;
  double fineBarrierRaise = 4.0;
  double meshWeight = 0.5;
  double coverageWeight = 0.1;
  double mapWeight = 1.0;
  double approximationWeight = 0.25;

  // Refinement where the exact map is distorted, after the fine phase.
  int refinementRounds = 1;
  int refinementIterations = 10;
  double refinementDistortion = 1.4;
  double squeezeDistortion = 10.0;
  double refinementGrowth = 0.25;

  // Error-bounded remeshing (maxError 0: off).
  double maxError = 0.0;
  int boundRefinementRounds = 8;
  int boundRefinementIterations = 10;
  double boundMargin = 0.9;
  int boundIterations = 20;

  // Resource bound: the common triangulation's vertex count at most, checked
  // after every remeshing (0: 20 times the largest input's vertex count, at
  // least 20 000). Reaching it ends the map without a certified result, so
  // that a bound or target error finer than the budget allows cannot run for
  // ever.
  int maxVertices = 0;

  // Energy and solver details.
  int approximationSamples = 50000;
  double minEdgeLength = 1e-3;
  double maxEdgeLength = 100.0;
  double decrementTolerance = 1e-4;
  double maxPointStep = 0.17632698070846498;
  int blockSolveInputs = 4;

  /// Called once per iteration; return false to abort (throws Aborted).
  std::function<bool(const SurfaceMapProgress&)> progress;
  Logger log;
};

} // namespace surfacemaps
