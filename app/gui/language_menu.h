#pragma once

class QMenu;

namespace devsurf::app {

class Workspace;

// View ▸ Language: the system's language, English, German or Japanese, remembered in the
// settings. The window builds its texts once, so a choice takes effect at the next start; when
// the design has no unsaved changes, DevSurf offers to restart with it now.
void addLanguageMenu(QMenu* view, Workspace* workspace);

} // namespace devsurf::app
