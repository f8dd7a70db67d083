#pragma once

#include <cstdint>

namespace devsurf::model {

// Stable ids of the coarse mesh's entities. They survive edits, undo and saving; OpenMesh
// handles never leave the model (they change when the mesh is rebuilt).
using VertexId = std::uint32_t;
using EdgeId = std::uint32_t;
using FaceId = std::uint32_t;
// A surface's id within its project: stable while surfaces are added or removed (indices are
// not); 0 means "not assigned yet" (Project::assignSurfaceIds).
using SurfaceId = std::uint32_t;

inline constexpr std::uint32_t kInvalidId = 0xffffffffu;

} // namespace devsurf::model
