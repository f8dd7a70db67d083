#include "vtk_interactor_styles.h"

#include <vtkObjectFactory.h>

namespace devsurf::views {

vtkStandardNewMacro(OrbitStyle);
vtkStandardNewMacro(PlanarStyle);

} // namespace devsurf::views
