#include "widgets/language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace resect {

namespace {

// objectNames of the translators installTranslations owns, to replace them later.
constexpr const char* kAppTranslatorName = "resect_app_translator";
constexpr const char* kQtTranslatorName = "resect_qt_translator";

void setError(QString* error, const QString& message) {
    if (error)
        *error = message;
}

} // namespace

QStringList availableLanguages() {
    return {QStringLiteral("en"), QStringLiteral("de"), QStringLiteral("fr")};
}

QString languageName(const QString& code) {
    if (code == QLatin1String("en"))
        return QStringLiteral("English");
    if (code == QLatin1String("de"))
        return QStringLiteral("Deutsch");
    if (code == QLatin1String("fr"))
        return QStringLiteral("Fran\u00e7ais");
    return {};
}

QString languageCode(const QString& text) {
    QString code = text.trimmed().toLower();
    for (qsizetype i = 0; i < code.size(); ++i)
        if (code[i] == QLatin1Char('_') || code[i] == QLatin1Char('-')) {
            code.truncate(i);
            break;
        }
    return availableLanguages().contains(code) ? code : QString();
}

QString chooseLanguage(const QString& commandLine, const QSettings& settings, const QLocale& system,
                       QString* error) {
    setError(error, {});
    const QString known = availableLanguages().join(QStringLiteral(", "));
    if (!commandLine.isEmpty()) {
        const QString code = languageCode(commandLine);
        if (code.isEmpty())
            setError(error, QCoreApplication::translate("resect::Language",
                                                        "unknown language \"%1\" (available: %2)")
                                .arg(commandLine, known));
        return code;
    }
    const QString saved = settings.value(QLatin1String(kLanguageSettingsKey)).toString();
    if (!saved.isEmpty()) {
        const QString code = languageCode(saved);
        if (!code.isEmpty())
            return code;
        setError(error, QCoreApplication::translate(
                            "resect::Language",
                            "the saved language \"%1\" is unknown (available: %2); it is ignored")
                            .arg(saved, known));
    }
    for (const QString& name : system.uiLanguages()) {
        const QString code = languageCode(name);
        if (!code.isEmpty())
            return code;
    }
    return QStringLiteral("en");
}

QString chooseLanguage(const QString& commandLine, const QSettings& settings, QString* error) {
    return chooseLanguage(commandLine, settings, QLocale::system(), error);
}

bool installTranslations(QCoreApplication& app, const QString& code, QString* error) {
    setError(error, {});
    const QString language = languageCode(code);
    if (language.isEmpty() || language != code.trimmed().toLower()) {
        setError(error, QCoreApplication::translate("resect::Language",
                                                    "unknown language \"%1\" (available: %2)")
                            .arg(code, availableLanguages().join(QStringLiteral(", "))));
        return false;
    }
    // Replace what an earlier call installed.
    for (QTranslator* old : app.findChildren<QTranslator*>(QString(), Qt::FindDirectChildrenOnly)) {
        if (old->objectName() == QLatin1String(kAppTranslatorName) ||
            old->objectName() == QLatin1String(kQtTranslatorName)) {
            QCoreApplication::removeTranslator(old);
            delete old;
        }
    }
    if (language == QLatin1String("en"))
        return true;

    auto* appTranslator = new QTranslator(&app);
    appTranslator->setObjectName(QLatin1String(kAppTranslatorName));
    const QString file = QStringLiteral(":/i18n/resect_studio_%1.qm").arg(language);
    if (!appTranslator->load(file)) {
        delete appTranslator;
        setError(error, QCoreApplication::translate("resect::Language",
                                                    "the translation %1 is missing or unreadable")
                            .arg(file));
        return false;
    }
    QCoreApplication::installTranslator(appTranslator);

    auto* qtTranslator = new QTranslator(&app);
    qtTranslator->setObjectName(QLatin1String(kQtTranslatorName));
    if (qtTranslator->load(QStringLiteral("qtbase_") + language,
                           QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qtTranslator);
    else
        delete qtTranslator;
    return true;
}

} // namespace resect
