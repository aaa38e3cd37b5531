// SurfaceMaps engine: EditHandlers and T's own handlers.
#include "map/EditHandlers.h"

namespace surfacemaps
{

namespace
{

/// The new faces' target lengths, barrier raises and cached energies.
void updateFaceData(CommonTriangulation& T, const EditedFaces& edited)
{
  for (std::size_t k = 0; k < edited.faces.size(); ++k)
  {
    const OpenMesh::FaceHandle f = edited.faces[k];
    const int t = edited.triangle[k];
    T.setTargetLength(f, (*edited.lengths)[t]);
    T.clearBarrierRaise(f);
    T.setFaceEnergy(f, (*edited.energies)[t]);
  }
}

/// The replaced faces' samples, each handed to the new face it lies in.
void trackSamples(CommonTriangulation& T, const EditedFaces& edited)
{
  if (!T.tracksSamples())
  {
    return;
  }
  for (std::size_t k = 0; k < edited.faces.size(); ++k)
  {
    for (int i = 0; i < T.numberOfInputs(); ++i)
    {
      const std::vector<int>& replaced = (*edited.samples)[i];
      std::vector<int>& samples = T.faceSamples(edited.faces[k], i);
      samples.clear();
      for (std::size_t s = 0; s < replaced.size(); ++s)
      {
        if ((*edited.assignment)[i][s] == edited.triangle[k])
        {
          samples.push_back(replaced[s]);
        }
      }
    }
  }
}

} // namespace

void EditHandlers::onEveryEdit(const EditHandler& handler)
{
  this->split.push_back(handler);
  this->collapse.push_back(handler);
  this->flip.push_back(handler);
}

EditHandlers triangulationHandlers(CommonTriangulation& T)
{
  EditHandlers handlers;
  handlers.onEveryEdit([&T](const EditedFaces& edited) { updateFaceData(T, edited); });
  handlers.onEveryEdit([&T](const EditedFaces& edited) { trackSamples(T, edited); });
  return handlers;
}

} // namespace surfacemaps
