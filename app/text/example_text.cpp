#include "example_text.h"

#include <QCoreApplication>

namespace devsurf::app {

QString exampleDescription(const std::string& name) {
    if (name == "sheet") {
        return QCoreApplication::translate("ExampleDialog",
                                           "A flat rectangle of size × size strips.");
    }
    if (name == "annulus") {
        return QCoreApplication::translate("ExampleDialog",
                                           "A flat annulus of size rings cut by radial rulings.");
    }
    if (name == "cylinder") {
        return QCoreApplication::translate("ExampleDialog",
                                           "A closed cylinder of strips, size sectors around.");
    }
    if (name == "fig8") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A flat square of size × size strips with curved creases, ready to fold: every "
            "interior crease carries the curved-fold condition and the bottom corners are "
            "pinned. Drag the middle vertices up (Drag tool, G).");
    }
    if (name == "fig6") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "Two strips joined by one curved crease with the curved-fold condition, the bottom "
            "corners pinned; size intervals per curve. Drag a top corner up to fold it.");
    }
    if (name == "fig13") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A disk with one curved crease between two strips, folded from a disk-shaped sheet "
            "it keeps; the crease's middle and the rim below it pinned; size faces per strip. "
            "Drag the top of the rim up and in towards the crease to fold it.");
    }
    if (name == "fig12") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A ring of size bands folded along concentric curved creases, mountain and valley in "
            "turn, exactly: every crease a fold in a horizontal plane, every band a piece of one "
            "cone. It keeps its development on its sheet, a ring whose edges wave with its eight "
            "lobes; three inner vertices pinned.");
    }
    if (name == "torus") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A closed torus of size bands of cones, 2 × size strips around: developable strip by "
            "strip but not from one sheet; its cutting pattern has one piece per band.");
    }
    if (name == "column") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A pleated column after Huffman's hexagonal column: a tube folded along size upright "
            "creases with the curved-fold condition, three bottom vertices pinned. It keeps its "
            "development around the cylinder it unrolls from. Drag a top vertex up or in.");
    }
    return QCoreApplication::translate("ExampleDialog",
                                       "A strip, a pointed strip, a cone and a planar patch; size "
                                       "intervals per curve.");
}

QString heldExampleDescription(const std::string& name) {
    if (name == "fig8") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "A flat square of size × size strips with curved creases carrying the curved-fold "
            "condition, holding its square sheet with the creases where they lie in it, its "
            "bottom-left corner pinned. Select the four middle vertices and drag them up (Drag "
            "tool, G) to fold it.");
    }
    if (name == "fig6") {
        return QCoreApplication::translate(
            "ExampleDialog",
            "Two strips joined by one curved crease with the curved-fold condition, holding its "
            "rectangular sheet with the crease where it lies in it, its bottom-left corner "
            "pinned; size intervals per curve. Select both top corners and drag them up and in "
            "towards the crease to fold it.");
    }
    return {};
}

} // namespace devsurf::app
