// surfacemap transfer --pictures: the carried point arrays drawn on both
// sides (see Pictures.h for the display they need).
//
// One function per kind of picture (continuous, categorical, colours) picks
// up an array; per-corner texture coordinates give a textured picture.
#pragma once

#include <string>
#include <vector>

class vtkSurfaceMapTransfer;

namespace surfacemap
{

/// The picture of point array `name` beside the transfer's output file:
/// <output without its extension>_<name>.png, every character of `name`
/// other than a letter, digit, '-', '_' or '.' replaced by '_'.
std::string transferPicturePath(const std::string& output, const std::string& name);

/// After `transfer` ran (input I on its port 1, its output on input J's
/// vertices): one picture per numeric point array it carried (not
/// SourceCellId, SourceBarycentric, TCoords, SpherePosition or Landmarks),
/// input I with its array and
/// input J with the received one side by side in the same colours,
/// at transferPicturePath(output, name), each written atomically:
/// - continuous arrays: a colour map over both sides' range (the magnitude
///   for several components), with a colour legend;
/// - categorical arrays: one distinct flat colour per label, each triangle in
///   the label most of its corners carry (no colour between labels), a
///   legend when there are at most 12 labels;
/// - colours (unsigned char, 3 or 4 components): drawn as they are;
/// and, when input I and the output have per-corner texture coordinates
/// ("CornerTCoords"), transferPicturePath(output, "texture"): both textured
/// with checkerboardTexture(), split at their seams.
/// Returns the paths written; throws std::runtime_error naming a file that
/// cannot be written.
std::vector<std::string> writeTransferPictures(vtkSurfaceMapTransfer* transfer,
  int from,
  int to,
  const std::string& output);

} // namespace surfacemap
