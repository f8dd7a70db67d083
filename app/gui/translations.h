#pragma once

#include <QLocale>
#include <QString>

namespace devsurf::app {

// Installs the interface translation for a locale: Qt's own (standard buttons and dialogs,
// qtbase_*.qm from the system's Qt translations) and DevSurf's (compiled in under :/i18n). For
// English only DevSurf's plural forms are loaded ("1 patch", "2 patches"). Replaces the ones
// installed by an earlier call. Returns whether DevSurf's translation was found.
bool installTranslations(const QLocale& locale);
// Removes what installTranslations() installed (tests switch languages).
void removeTranslations();

// View ▸ Language: the interface language chosen ("en", "de", "ja"), kept in the settings;
// empty: the system's.
QString chosenLanguage();
void setChosenLanguage(const QString& code);
// The locale the interface starts in: the chosen language, else the system's.
QLocale interfaceLocale();
// At start: makes interfaceLocale() the default locale and installs its translations.
bool installInterfaceTranslations();

} // namespace devsurf::app
