#pragma once

// How each layer of a cutting pattern looks in every format: the same name, colour and line
// style in DXF, SVG, PDF and on paper, so a designer recognises a layer wherever it appears.

#include "model/pattern/cutting_pattern.h"

#include <array>
#include <cstdint>
#include <vector>

namespace devsurf::io {

struct LayerStyle {
    model::PatternLayer layer;
    const char* name;           // as model::patternLayerName, the name in every format
    int aci;                    // AutoCAD colour index for DXF
    std::uint32_t rgb;          // 0xRRGGBB for SVG, PDF and printing (readable on white paper)
    const char* linetype;       // DXF linetype name
    std::vector<double> dashes; // mm: dash, gap, dash, gap… (empty: continuous; 0: a dot)
    double strokeWidth;         // mm on paper and in SVG
    bool onByDefault;           // DXF layer on, SVG layer shown
};

// The style of one layer.
const LayerStyle& layerStyle(model::PatternLayer layer);

// Every layer in the order of model::PatternLayer.
const std::array<LayerStyle, model::kPatternLayerCount>& layerStyles();

// A set of layers to write (bit i: PatternLayer i).
using LayerMask = std::uint32_t;
inline constexpr LayerMask kAllLayers = (1u << model::kPatternLayerCount) - 1u;
inline constexpr LayerMask layerBit(model::PatternLayer layer) {
    return 1u << static_cast<unsigned>(layer);
}

} // namespace devsurf::io
