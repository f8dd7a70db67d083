#pragma once

#include <optional>
#include <string>

namespace devsurf::io {

// dxflib trusts the counts a file announces (vertices of an LWPOLYLINE, knots and control
// points of a SPLINE, vertices of a LEADER) and writes before the first vertex where a bulge
// comes first; and a line longer than its buffer makes it read forever. This scan refuses such
// files before dxflib sees them: the reason, or nullopt.
std::optional<std::string> unsafeDxfContent(const std::string& bytes);

} // namespace devsurf::io
