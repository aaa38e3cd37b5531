// SurfaceMaps engine: the order in which the engine maps its inputs.
#pragma once

#include "map/MapInput.h"
#include "map/MapPairs.h"

#include <vector>

namespace surfacemaps
{

/// The order in which the engine maps `inputs` (entry k: the caller's index
/// of the engine's input k). Whatever the pairs, the engine's first input is
/// special: T starts from its embedding and the others' embeddings are
/// rotated onto its frame. The pairings that name no input (All, Mean) with
/// three or more inputs therefore start from an order of their own, so that
/// the map, and every mean or statistic over it, does not depend on the
/// order in which the caller gives the inputs: first the most typical input
/// (the smallest sum of shape distances to the others), then the others by
/// that sum, ties by content. The shape distance is the Procrustes distance
/// of the landmark configurations when there are landmarks (three or more),
/// else the difference of the unit-area surfaces' principal second moments.
/// Star, Sequence and Cycle keep the caller's order, which defines their
/// pairs, as does a map of one or two inputs. Every number the order depends
/// on is computed the same way for any permutation of the inputs.
std::vector<int> mappingOrder(const std::vector<MapInput>& inputs, PairScheme pairs);

} // namespace surfacemaps
