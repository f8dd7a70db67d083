#include "translations.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
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

QString chosenLanguage() {
    const QString code = QSettings().value(QStringLiteral("interface/language")).toString();
    const QStringList known{QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("ja")};
    return known.contains(code) ? code : QString();
}

void setChosenLanguage(const QString& code) {
    if (code.isEmpty()) {
        QSettings().remove(QStringLiteral("interface/language"));
    } else {
        QSettings().setValue(QStringLiteral("interface/language"), code);
    }
}

QLocale interfaceLocale() {
    const QString code = chosenLanguage();
    if (code.isEmpty()) {
        return QLocale::system();
    }
    // English as in the United States, the language the interface is written in.
    return code == QLatin1String("en") ? QLocale(QLocale::English, QLocale::UnitedStates)
                                       : QLocale(code);
}

bool installInterfaceTranslations() {
    const QLocale locale = interfaceLocale();
    QLocale::setDefault(locale);
    return installTranslations(locale);
}

} // namespace devsurf::app
