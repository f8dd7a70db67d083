#pragma once

namespace devsurf::views {

// What the 3D view's surfaces are coloured by.
enum class ColourBy {
    Patch,          // the patch palette
    Developability, // normalised |det(a−b, a′, b′)| of every sampled strip quad
    Flatness,       // δ = distance of the diagonals / mean of the two shortest edges
    AngleDefect,    // |2π − Σ angles| at the interior vertices of the sampled mesh (radians)
};

} // namespace devsurf::views
