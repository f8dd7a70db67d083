#include "face_type_text.h"

#include <QCoreApplication>

namespace devsurf::app {

QString faceTypeText(model::FaceType type) {
    switch (type) {
    case model::FaceType::StripSRSR:
        return QCoreApplication::translate("FaceType", "strip (SRSR)");
    case model::FaceType::StripSRS:
        return QCoreApplication::translate("FaceType", "pointed strip (SRS)");
    case model::FaceType::ConeSRR:
        return QCoreApplication::translate("FaceType", "cone (SRR)");
    case model::FaceType::Planar:
        return QCoreApplication::translate("FaceType", "planar patch");
    case model::FaceType::Invalid:
        break;
    }
    return QCoreApplication::translate("FaceType", "invalid labelling");
}

} // namespace devsurf::app
