#pragma once

#include "model/composite_surface.h"

#include <QString>

namespace devsurf::app {

// What the panels call a face type, translated.
QString faceTypeText(model::FaceType type);

} // namespace devsurf::app
