#pragma once
// The language of the studio's user interface: which ones exist, which one to use (command
// line, then the saved preference, then the system's), and installing the translators.
//
// The application's translations are Qt Linguist files translations/resect_studio_CODE.ts,
// compiled to .qm and embedded in resect_widgets under ":/i18n/resect_studio_CODE.qm"
// (widgets/CMakeLists.txt; tools/update_translations.sh refreshes the .ts files from the
// sources of widgets/ and app/studio/). English is the source language: it needs no file.
// Qt's own strings (standard buttons, dialogs) come from Qt's qtbase_CODE.qm in
// QLibraryInfo::path(QLibraryInfo::TranslationsPath) (Debian: qt6-translations-l10n).

#include <QLocale>
#include <QString>
#include <QStringList>

class QCoreApplication;
class QSettings;

namespace resect {

/// The settings key holding the preferred language code.
inline constexpr const char* kLanguageSettingsKey = "language";

/// The interface languages, English (the source) first: {"en", "de", "fr"}.
QStringList availableLanguages();

/// The language's name in itself ("English", "Deutsch", "Français"), for menus; empty for
/// an unknown code.
QString languageName(const QString& code);

/// The available language `text` names, or empty: a code ("de"), in any case ("DE"), or a
/// locale name whose language is available ("de_CH", "fr-FR").
QString languageCode(const QString& text);

/// The language to use: `commandLine` if not empty, else the preference `settings` holds
/// under kLanguageSettingsKey, else the first of `system.uiLanguages()` that is available,
/// else "en".
/// - An unknown `commandLine` is an error: the result is empty and *error (if given) says
///   which code and which ones exist.
/// - An unknown saved preference is skipped (it may come from another version): the result
///   is the next choice and *error (if given) receives a warning naming it.
/// Otherwise *error is cleared.
QString chooseLanguage(const QString& commandLine, const QSettings& settings, const QLocale& system,
                       QString* error = nullptr);
/// As above with the system's locale (QLocale::system()).
QString chooseLanguage(const QString& commandLine, const QSettings& settings,
                       QString* error = nullptr);

/// Installs the translators for `code` into `app`, replacing those a previous call
/// installed (the translators are children of `app`). "en" installs nothing (and removes a
/// previous language) and succeeds. Returns false, with the reason in *error, for an
/// unknown code or when the application's translation ":/i18n/resect_studio_CODE.qm"
/// cannot be loaded; Qt's own qtbase translation is installed when it is found and its
/// absence is not an error.
bool installTranslations(QCoreApplication& app, const QString& code, QString* error = nullptr);

} // namespace resect
