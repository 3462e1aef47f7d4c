// Internal to medial/: CGAL's Delaunay triangulation of the samples, each vertex carrying its
// sample's index.
#pragma once

#include <atomic>
#include <string>
#include <vector>

#include "../progress.h"
#include "../sampling/samples.h"
#include "delaunay_3.h"

namespace cadmedial::internal {

/// Inserts the samples into dt along CGAL's spatial sort (deterministic). handle[s] is sample s's
/// vertex (null for a sample that coincides with an earlier one); rank[s] its place in the
/// insertion order. Progress is reported under `stage`. Throws Cancelled soon after `give_up`
/// (if given) is set.
void triangulate(const Samples& samples, Delaunay& dt, std::vector<Vertex>& handle, std::vector<int>& rank,
                 const Progress& progress, const std::string& stage, const std::atomic<bool>* give_up = nullptr);

}  // namespace cadmedial::internal
