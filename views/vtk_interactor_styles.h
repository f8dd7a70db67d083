#pragma once

// Internal to views/: includes VTK.

#include <vtkInteractorStyleTrackballCamera.h>

namespace devsurf::views {

// Trackball camera for the 3D view. Key presses are left to the application (VTK's default
// keys switch to wireframe, start a fly-to or quit the event loop).
class OrbitStyle : public vtkInteractorStyleTrackballCamera {
public:
    static OrbitStyle* New();
    vtkTypeMacro(OrbitStyle, vtkInteractorStyleTrackballCamera) void OnChar() override {}
    void OnKeyPress() override {}

protected:
    OrbitStyle() = default;
    ~OrbitStyle() override = default;
};

// Pan and zoom only, for the development view: the left and middle buttons pan, the right
// button and the wheel zoom, and nothing rotates the sheet out of its plane.
class PlanarStyle : public vtkInteractorStyleTrackballCamera {
public:
    static PlanarStyle* New();
    vtkTypeMacro(PlanarStyle, vtkInteractorStyleTrackballCamera) void OnLeftButtonDown() override {
        Superclass::OnMiddleButtonDown();
    }
    void OnLeftButtonUp() override { Superclass::OnMiddleButtonUp(); }
    void Rotate() override {}
    void Spin() override {}
    void OnChar() override {}
    void OnKeyPress() override {}

protected:
    PlanarStyle() = default;
    ~PlanarStyle() override = default;
};

} // namespace devsurf::views
