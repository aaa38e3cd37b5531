#include "map/MapSettings.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace surfacemaps
{

namespace
{

using Options = SurfaceMapOptions;

template<typename T>
MapSetting setting(const char* name,
  const char* flag,
  SettingKind kind,
  T Options::*field,
  double minimum,
  double maximum,
  const char* doc)
{
  MapSetting s{ name, flag, nullptr, kind, minimum, maximum, nullptr, doc, nullptr, nullptr };
  s.get = [field](const Options& o) { return static_cast<double>(o.*field); };
  s.set = [field](Options& o, double value) { o.*field = static_cast<T>(value); };
  return s;
}

MapSetting real(const char* name,
  const char* flag,
  double Options::*field,
  double minimum,
  double maximum,
  const char* doc)
{
  return setting(name, flag, SettingKind::Real, field, minimum, maximum, doc);
}

MapSetting count(const char* name,
  const char* flag,
  int Options::*field,
  double minimum,
  double maximum,
  const char* doc)
{
  return setting(name, flag, SettingKind::Count, field, minimum, maximum, doc);
}

MapSetting toggle(const char* name,
  const char* flag,
  const char* offFlag,
  bool Options::*field,
  const char* doc)
{
  MapSetting s = setting(name, flag, SettingKind::Switch, field, 0.0, 1.0, doc);
  s.offFlag = offFlag;
  return s;
}

/// Which pairs the distortion term measures.
void pairSettings(std::vector<MapSetting>& table)
{
  MapSetting pairs{ "PairMode",
    "pairs",
    nullptr,
    SettingKind::Choice,
    0.0,
    3.0,
    "star|sequence|cycle|all",
    "Pairs whose map distortion is minimised with three or more inputs: (0, i), (i, i+1), "
    "(i, i+1) and (N-1, 0), or every pair.",
    [](const Options& o) { return static_cast<double>(o.pairs); },
    [](Options& o, double value) { o.pairs = static_cast<PairMode>(static_cast<int>(value)); } };
  table.push_back(pairs);
}

/// The landmark phase.
void landmarkSettings(std::vector<MapSetting>& table)
{
  table.push_back(count("LandmarkIterations",
    "landmark-iterations",
    &Options::landmarkIterations,
    0,
    100000,
    "Iteration cap of the landmark phase (barrier and landmark terms only; runs only with "
    "landmarks; 0 skips it). One iteration: improving splits, collapses, flips, one Newton step."));
  table.push_back(real("LandmarkWeight",
    "landmark-weight",
    &Options::landmarkWeight,
    0,
    1e12,
    "Weight of the landmark term in the landmark phase."));
  table.push_back(real("LandmarkBarrierWeight",
    "landmark-barrier-weight",
    &Options::landmarkBarrierWeight,
    1e-12,
    1e6,
    "Weight of the bijectivity barrier in the landmark phase."));
  table.push_back(real("LandmarkTolerance",
    "landmark-tolerance",
    &Options::landmarkTolerance,
    0,
    1,
    "Distance on the sphere below which every landmark counts as reached."));
  table.push_back(toggle("RelaxLandmarkPhase",
    "landmark-relaxation",
    "no-landmark-relaxation",
    &Options::relaxLandmarkPhase,
    "Once the landmarks are reached, go on with Newton steps and flips only until the landmark "
    "phase converges, so the barrier relaxes T around the moved landmarks; off: end the phase "
    "as soon as they are reached."));
  table.push_back(toggle("KeepLandmarks",
    "keep-landmarks",
    "release-landmarks",
    &Options::keepLandmarks,
    "After the landmark phase, snap T's landmark vertices exactly onto their input vertices and "
    "lock them; off: release them to the optimisation."));
}

/// The coarse and fine phases and the weights of the energy.
void phaseSettings(std::vector<MapSetting>& table)
{
  table.push_back(count("CoarseIterations",
    "coarse-iterations",
    &Options::coarseIterations,
    0,
    100000,
    "Iteration cap of the coarse phase (0 skips it). A phase also ends when no edit lowers the "
    "energy and the Newton decrement is below DecrementTolerance."));
  table.push_back(real("CoarseError",
    "coarse-error",
    &Options::coarseError,
    1e-6,
    1,
    "Approximation error eps of the coarse phase (unit-area units): approximation weight "
    "1/eps^2, and the error the curvature sizing aims at."));
  table.push_back(real("CoarseBarrierWeight",
    "coarse-barrier-weight",
    &Options::coarseBarrierWeight,
    1e-12,
    1e6,
    "Weight of the bijectivity barrier in the coarse phase."));
  table.push_back(count("FineIterations",
    "fine-iterations",
    &Options::fineIterations,
    0,
    100000,
    "Iteration cap of the fine phase (0 skips it, and the refinement with it)."));
  table.push_back(real("TargetError",
    "target-error",
    &Options::targetError,
    1e-6,
    1,
    "Approximation error eps of the fine phase (unit-area units): approximation weight "
    "1/eps^2 and the curvature sizing's error; smaller values give a larger T."));
  table.push_back(real("FineBarrierWeight",
    "fine-barrier-weight",
    &Options::fineBarrierWeight,
    1e-12,
    1e6,
    "Weight of the bijectivity barrier in the fine phase and after it."));
  table.push_back(real("FineBarrierRaise",
    "fine-barrier-raise",
    &Options::fineBarrierRaise,
    1,
    1e3,
    "From the fine phase on, the barrier weight of a triangle of T that inverts on a sphere at a "
    "Newton step's full step is multiplied by this (at most three times), so the next steps "
    "see the wall they ran into; 1: the same weight for every triangle."));
  table.push_back(real("MeshWeight",
    "mesh-weight",
    &Options::meshWeight,
    0,
    1e6,
    "Weight of the mesh-quality term (coarse phase on)."));
  table.push_back(real("CoverageWeight",
    "coverage-weight",
    &Options::coverageWeight,
    0,
    1e6,
    "Weight of the coverage term (coarse phase on): per triangle of T and input, its lifted "
    "area against the input area its sphere triangle covers; keeps T's triangles from being "
    "slivers on one sphere over a fold of the surface, where the exact map squeezes."));
  table.push_back(real("MapWeight",
    "map-weight",
    &Options::mapWeight,
    0,
    1e6,
    "Weight of the map-distortion term (coarse phase on): more, a lower distortion."));
  table.push_back(real("ApproximationWeight",
    "approximation-weight",
    &Options::approximationWeight,
    0,
    1e6,
    "Weight of the surface-approximation term (coarse phase on): more, a T and an exact map "
    "closer to the inputs."));
}

/// The refinement where the exact map is distorted.
void refinementSettings(std::vector<MapSetting>& table)
{
  table.push_back(count("RefinementRounds",
    "refinement-rounds",
    &Options::refinementRounds,
    0,
    100,
    "After the fine phase, rounds that shrink the sizing around input triangles whose exact-map "
    "distortion exceeds a threshold, then iterate again with the fine phase's settings; rounds "
    "stop when no triangle exceeds it (0: off)."));
  table.push_back(count("RefinementIterations",
    "refinement-iterations",
    &Options::refinementIterations,
    1,
    100000,
    "Iterations of each refinement round (at most FineIterations)."));
  table.push_back(real("RefinementDistortion",
    "refinement-distortion",
    &Options::refinementDistortion,
    1,
    1e12,
    "The first round's threshold on the exact map's distortion max(s1, 1/s2) of an input "
    "triangle: T gets more vertices where the map is distorted."));
  table.push_back(real("SqueezeDistortion",
    "squeeze-distortion",
    &Options::squeezeDistortion,
    1,
    1e12,
    "The later rounds' threshold: while the exact map squeezes an input triangle inside a T "
    "triangle (which T's own map cannot see) beyond this, another round of iterations runs, "
    "with the sizing as it is."));
  table.push_back(real("RefinementGrowth",
    "refinement-growth",
    &Options::refinementGrowth,
    0,
    1e12,
    "Bounds the first round's refinement: with a fraction `area` of an input above the "
    "threshold the sizing there shrinks by 1/sqrt(1 + growth/area), at most by half (0: the "
    "round only iterates)."));
}

/// Error-bounded remeshing.
void boundSettings(std::vector<MapSetting>& table)
{
  table.push_back(real("MaxError",
    "max-error",
    &Options::maxError,
    0,
    1,
    "Error-bounded remeshing: the largest distance allowed between an input vertex and its base "
    "point on T, as a fraction of the input's bounding-box diagonal; refined until met, then "
    "optimised with the bound as a barrier and certified on every vertex (0: off)."));
  table.push_back(count("BoundRefinementRounds",
    "bound-refinement-rounds",
    &Options::boundRefinementRounds,
    0,
    100,
    "Rounds of refinement towards MaxError at most; a vertex still beyond the bound after them "
    "is an error (one only beyond BoundMargin of it goes on to the bound phase)."));
  table.push_back(count("BoundRefinementIterations",
    "bound-refinement-iterations",
    &Options::boundRefinementIterations,
    0,
    100000,
    "Iterations of each refinement round towards MaxError."));
  table.push_back(real("BoundMargin",
    "bound-margin",
    &Options::boundMargin,
    0.01,
    1,
    "Refinement towards MaxError goes on while a vertex is beyond this fraction of the bound, "
    "so that the barrier starts finite."));
  table.push_back(count("BoundIterations",
    "bound-iterations",
    &Options::boundIterations,
    0,
    100000,
    "Iterations with the hard bound as a barrier when MaxError is set."));
}

/// Energy and solver details.
void detailSettings(std::vector<MapSetting>& table)
{
  table.push_back(count("MaxVertices",
    "max-vertices",
    &Options::maxVertices,
    0,
    1e9,
    "Vertex budget of T: a map whose T would grow beyond it ends without a certified result, "
    "naming the phase (0: 20 times the largest input's vertex count, at least 20 000)."));
  table.push_back(count("ApproximationSamples",
    "approximation-samples",
    &Options::approximationSamples,
    1,
    1e9,
    "Input vertices per input the approximation term uses at most (an evenly spread subsample "
    "of larger inputs; every vertex with MaxError)."));
  table.push_back(real("MinEdgeLength",
    "min-edge-length",
    &Options::minEdgeLength,
    1e-9,
    1e9,
    "Smallest edge length of the curvature sizing (unit-area units)."));
  table.push_back(real("MaxEdgeLength",
    "max-edge-length",
    &Options::maxEdgeLength,
    1e-9,
    1e9,
    "Largest edge length of the curvature sizing (unit-area units)."));
  table.push_back(real("DecrementTolerance",
    "decrement-tolerance",
    &Options::decrementTolerance,
    0,
    1,
    "A phase has converged when no edit lowers the energy and the Newton decrement "
    "sqrt(-d.g) is below this."));
  table.push_back(real("MaxPointStep",
    "max-point-step",
    &Options::maxPointStep,
    1e-6,
    1e3,
    "Largest tangent step (tan of the angle) of one point in a Newton step; the whole step is "
    "scaled down to respect it, never clamped per point."));
  table.push_back(count("BlockSolveInputs",
    "block-solve-inputs",
    &Options::blockSolveInputs,
    0,
    1e6,
    "From this many inputs on, each Newton system is solved by conjugate gradients "
    "preconditioned with every sphere embedding's own block (time linear in the number of "
    "inputs) instead of one Cholesky factorisation of all embeddings together (whose cost grows "
    "with the cube of the number of inputs); 0: always the factorisation."));
}

std::vector<MapSetting> buildTable()
{
  std::vector<MapSetting> table;
  const auto add = [&table](void (*settings)(std::vector<MapSetting>&), const char* topic)
  {
    const std::size_t first = table.size();
    settings(table);
    for (std::size_t k = first; k < table.size(); ++k)
    {
      table[k].topic = topic;
    }
  };
  add(pairSettings, "Pairs");
  add(landmarkSettings, "Landmark phase");
  add(phaseSettings, "Coarse and fine phases");
  add(refinementSettings, "Refinement");
  add(boundSettings, "Error bound");
  add(detailSettings, "Limits and solver");
  return table;
}

} // namespace

double MapSetting::clamp(double value) const
{
  if (std::isnan(value))
  {
    return this->defaultValue();
  }
  value = std::clamp(value, this->minimum, this->maximum);
  return this->kind == SettingKind::Real ? value : std::round(value);
}

std::string MapSetting::format(double value) const
{
  switch (this->kind)
  {
    case SettingKind::Switch:
      return value != 0.0 ? "on" : "off";
    case SettingKind::Choice:
    {
      const std::vector<std::string> names = this->choiceNames();
      const int k = static_cast<int>(value);
      return k >= 0 && k < static_cast<int>(names.size()) ? names[k] : std::to_string(k);
    }
    default:
    {
      std::ostringstream text;
      text << value;
      return text.str();
    }
  }
}

std::vector<std::string> MapSetting::choiceNames() const
{
  std::vector<std::string> names;
  if (!this->choices)
  {
    return names;
  }
  std::istringstream text(this->choices);
  for (std::string name; std::getline(text, name, '|');)
  {
    names.push_back(name);
  }
  return names;
}

bool MapSetting::parse(const std::string& text, double& value) const
{
  const std::vector<std::string> names = this->choiceNames();
  for (std::size_t c = 0; c < names.size(); ++c)
  {
    if (names[c] == text)
    {
      value = static_cast<double>(c);
      return true;
    }
  }
  if (this->kind == SettingKind::Choice)
  {
    return false;
  }
  std::size_t used = 0;
  try
  {
    value = std::stod(text, &used);
  }
  catch (const std::exception&)
  {
    return false;
  }
  return used == text.size() && value >= this->minimum && value <= this->maximum &&
    (this->kind == SettingKind::Real || value == std::round(value));
}

const std::vector<MapSetting>& mapSettings()
{
  static const std::vector<MapSetting> table = buildTable();
  return table;
}

const MapSetting* findMapSetting(const std::string& name)
{
  for (const MapSetting& s : mapSettings())
  {
    if (name == s.name)
    {
      return &s;
    }
  }
  return nullptr;
}

bool parseSettingFlag(const std::vector<std::string>& args,
  std::size_t& i,
  SurfaceMapOptions& options)
{
  const std::string& arg = args[i];
  for (const MapSetting& s : mapSettings())
  {
    const std::string on = std::string("--") + s.flag;
    if (s.kind == SettingKind::Switch)
    {
      if (arg == on || (s.offFlag && arg == std::string("--") + s.offFlag))
      {
        s.set(options, arg == on ? 1.0 : 0.0);
        return true;
      }
      continue;
    }
    if (arg != on)
    {
      continue;
    }
    if (i + 1 >= args.size())
    {
      throw std::invalid_argument(arg + " needs a value");
    }
    const std::string& text = args[++i];
    double value = 0.0;
    if (!s.parse(text, value))
    {
      throw std::invalid_argument(arg + " takes " +
        (s.kind == SettingKind::Choice ? std::string(s.choices)
                                       : s.format(s.minimum) + " to " + s.format(s.maximum)) +
        ", not '" + text + "'");
    }
    s.set(options, value);
    return true;
  }
  return false;
}

} // namespace surfacemaps
