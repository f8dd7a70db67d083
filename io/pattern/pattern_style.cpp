#include "pattern_style.h"

namespace devsurf::io {

using model::PatternLayer;

const std::array<LayerStyle, model::kPatternLayerCount>& layerStyles() {
    // Folds follow the origami convention (mountain dash-dot, valley dashed); cut lines are
    // solid and black so that cutter software that maps colours to operations keeps them apart.
    static const std::array<LayerStyle, model::kPatternLayerCount> styles{{
        {PatternLayer::Cut, "CUT", 7, 0x000000, "CONTINUOUS", {}, 0.25, true},
        {PatternLayer::Mountain,
         "MOUNTAIN",
         1,
         0xd01010,
         "DASHDOT",
         {6.0, 2.0, 0.0, 2.0},
         0.25,
         true},
        {PatternLayer::Valley, "VALLEY", 5, 0x1040d0, "DASHED", {4.0, 2.0}, 0.25, true},
        {PatternLayer::Crease, "CREASE", 6, 0xa020a0, "DASHED2", {2.0, 1.5}, 0.25, true},
        {PatternLayer::Score, "SCORE", 8, 0x909090, "DOT", {0.0, 1.5}, 0.15, false},
        {PatternLayer::Seam, "SEAM", 3, 0x109030, "HIDDEN", {1.0, 1.0}, 0.2, true},
        {PatternLayer::Labels, "LABELS", 4, 0x007878, "CONTINUOUS", {}, 0.2, true},
    }};
    return styles;
}

const LayerStyle& layerStyle(PatternLayer layer) {
    return layerStyles()[static_cast<std::size_t>(layer)];
}

} // namespace devsurf::io
