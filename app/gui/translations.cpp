#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

#include <memory>

namespace devsurf::app {

namespace {

std::unique_ptr<QTranslator>& qtTranslator() {
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

std::unique_ptr<QTranslator>& ownTranslator() {
    static std::unique_ptr<QTranslator> translator;
    return translator;
}

} // namespace

void removeTranslations() {
    for (auto* slot : {&qtTranslator(), &ownTranslator()}) {
        if (*slot) {
            QCoreApplication::removeTranslator(slot->get());
            slot->reset();
        }
    }
}

bool installTranslations(const QLocale& locale) {
    removeTranslations();
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath))) {
        QCoreApplication::installTranslator(qt.get());
        qtTranslator() = std::move(qt);
    }
    auto own = std::make_unique<QTranslator>();
    // An English or unknown locale gets the English plural forms.
    const bool found = own->load(locale, QStringLiteral("devsurf"), QStringLiteral("_"),
                                 QStringLiteral(":/i18n")) ||
                       own->load(QStringLiteral(":/i18n/devsurf_en.qm"));
    if (found) {
        QCoreApplication::installTranslator(own.get());
        ownTranslator() = std::move(own);
    }
    return found;
}

} // namespace devsurf::app
