// Interface languages (widgets/language.h) and the translation files:
// - the .qm files are embedded in resect_widgets and reach an executable linking it;
// - installTranslations("de"/"fr") translates the studio's strings and Qt's own, "en" and a
//   later language replace what was installed, an unknown code is refused naming it;
// - chooseLanguage: command line > saved preference > system locale > "en";
// - every message of translations/resect_studio_{de,fr}.ts (read from the source tree) is
//   translated: no unfinished or empty translation, every numerus form filled, the same
//   placeholders (%1 ... %9, %n) as the source and the same number of '&' accelerators;
// - the .ts files hold exactly the strings lupdate finds in widgets/ and app/studio/ now
//   (otherwise: run tools/update_translations.sh and translate what is new).
#include "widgets/language.h"

#include <QApplication>
#include <QDir>
#include <QFile>
#include <QLibraryInfo>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QSettings>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

using namespace resect;

namespace {

struct TsMessage {
    QString context;
    QString source;
    QString type;             ///< the translation's type attribute ("unfinished", "vanished", ...)
    QStringList translations; ///< one, or every numerus form
    bool numerus = false;
};

/// The messages of a .ts file; `error` receives an XML error.
QList<TsMessage> readTs(const QString& path, QString& language, QString& error) {
    QList<TsMessage> messages;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) {
        error = path + ": cannot read";
        return messages;
    }
    QXmlStreamReader xml(&file);
    QString context;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        if (xml.name() == QLatin1String("TS")) {
            language = xml.attributes().value("language").toString();
        } else if (xml.name() == QLatin1String("name")) {
            context = xml.readElementText();
        } else if (xml.name() == QLatin1String("message")) {
            TsMessage m;
            m.context = context;
            m.numerus = xml.attributes().value("numerus") == QLatin1String("yes");
            while (xml.readNextStartElement()) {
                if (xml.name() == QLatin1String("source")) {
                    m.source = xml.readElementText();
                } else if (xml.name() == QLatin1String("translation")) {
                    m.type = xml.attributes().value("type").toString();
                    if (m.numerus) {
                        while (xml.readNextStartElement()) {
                            if (xml.name() == QLatin1String("numerusform"))
                                m.translations << xml.readElementText();
                            else
                                xml.skipCurrentElement();
                        }
                    } else {
                        m.translations << xml.readElementText();
                    }
                } else {
                    xml.skipCurrentElement();
                }
            }
            messages << m;
        }
    }
    if (xml.hasError())
        error = QString("%1:%2: %3").arg(path).arg(xml.lineNumber()).arg(xml.errorString());
    return messages;
}

/// The placeholders (%1 ... %99, %n, %L1) of a text, sorted, with repetitions.
QStringList placeholders(const QString& text) {
    QStringList found;
    static const QRegularExpression re(QStringLiteral("%L?(\\d+|n)"));
    for (auto it = re.globalMatch(text); it.hasNext();)
        found << it.next().captured(0);
    found.sort();
    return found;
}

/// Accelerator markers: '&' not followed by '&' (an escaped ampersand).
int accelerators(const QString& text) {
    int count = 0;
    for (qsizetype i = 0; i < text.size(); ++i) {
        if (text[i] != QLatin1Char('&'))
            continue;
        if (i + 1 < text.size() && text[i + 1] == QLatin1Char('&')) {
            ++i;
            continue;
        }
        ++count;
    }
    return count;
}

QString tsPath(const QString& code) {
    return QStringLiteral(RESECT_SOURCE_DIR "/translations/resect_studio_%1.ts").arg(code);
}

} // namespace

class TestLanguage : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { QVERIFY(installTranslations(*qApp, "en")); }

    void translationsAreEmbedded() {
        for (const QString code : {"de", "fr"}) {
            const QString file = QStringLiteral(":/i18n/resect_studio_%1.qm").arg(code);
            QVERIFY2(QFile::exists(file), qPrintable(file + " is not linked into the executable"));
        }
        QCOMPARE(availableLanguages(), (QStringList{"en", "de", "fr"}));
    }

    void installTranslates_data() {
        QTest::addColumn<QString>("code");
        QTest::addColumn<QString>("file");
        QTest::addColumn<QString>("open");
        QTest::addColumn<QString>("cancel"); // Qt's own (qtbase): a standard button
        QTest::newRow("de") << "de"
                            << "&Datei" << QString::fromUtf8("Ö&ffnen...") << "Abbrechen";
        QTest::newRow("fr") << "fr"
                            << "&Fichier"
                            << "&Ouvrir..."
                            << "Annuler";
        QTest::newRow("en") << "en"
                            << "&File"
                            << "&Open..."
                            << "Cancel";
    }
    void installTranslates() {
        QFETCH(QString, code);
        QFETCH(QString, file);
        QFETCH(QString, open);
        QFETCH(QString, cancel);
        // Another language first: the new one must replace it, not stack on it.
        QString error;
        QVERIFY2(installTranslations(*qApp, code == "de" ? "fr" : "de", &error), qPrintable(error));
        QVERIFY2(installTranslations(*qApp, code, &error), qPrintable(error));
        QVERIFY(error.isEmpty());
        QCOMPARE(QCoreApplication::translate("resect::MainWindow", "&File"), file);
        QCOMPARE(QCoreApplication::translate("resect::MainWindow", "&Open..."), open);
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), cancel);
        if (code != "en") {
            const QString three = QCoreApplication::translate(
                "resect::ExportRunner", "Exported %n file(s) to %1; the expectations passed.",
                nullptr, 3);
            QVERIFY2(three.startsWith("3 ") && !three.startsWith("3 file"), qPrintable(three));
        }
    }

    void unknownLanguagesAreRefused() {
        QString error;
        QVERIFY(!installTranslations(*qApp, "xx", &error));
        QVERIFY2(error.contains("\"xx\"") && error.contains("en, de, fr"), qPrintable(error));
        QCOMPARE(QCoreApplication::translate("resect::MainWindow", "&File"), QString("&File"));
        QVERIFY(!installTranslations(*qApp, "de_DE", &error)); // install takes a code only
        QVERIFY(installTranslations(*qApp, "DE", &error));
        QCOMPARE(QCoreApplication::translate("resect::MainWindow", "&File"), QString("&Datei"));
    }

    void chooseLanguagePrecedence_data() {
        QTest::addColumn<QString>("commandLine");
        QTest::addColumn<QString>("saved");  // empty: no preference
        QTest::addColumn<QString>("system"); // a locale name
        QTest::addColumn<QString>("expected");
        QTest::addColumn<bool>("warns");
        QTest::newRow("command line wins") << "fr"
                                           << "de"
                                           << "de_DE"
                                           << "fr" << false;
        QTest::newRow("command line, locale form") << "fr_CA"
                                                   << ""
                                                   << "C"
                                                   << "fr" << false;
        QTest::newRow("command line unknown") << "xx"
                                              << "de"
                                              << "de_DE"
                                              << "" << true;
        QTest::newRow("preference next") << ""
                                         << "de"
                                         << "fr_FR"
                                         << "de" << false;
        QTest::newRow("unknown preference skipped") << ""
                                                    << "klingon"
                                                    << "fr_FR"
                                                    << "fr" << true;
        QTest::newRow("system next") << ""
                                     << ""
                                     << "fr_BE"
                                     << "fr" << false;
        QTest::newRow("system German") << ""
                                       << ""
                                       << "de_AT"
                                       << "de" << false;
        QTest::newRow("unavailable system: English") << ""
                                                     << ""
                                                     << "ja_JP"
                                                     << "en" << false;
        QTest::newRow("C locale: English") << ""
                                           << ""
                                           << "C"
                                           << "en" << false;
    }
    void chooseLanguagePrecedence() {
        QFETCH(QString, commandLine);
        QFETCH(QString, saved);
        QFETCH(QString, system);
        QFETCH(QString, expected);
        QFETCH(bool, warns);
        QTemporaryDir dir;
        QSettings settings(dir.filePath("settings.ini"), QSettings::IniFormat);
        if (!saved.isEmpty())
            settings.setValue(kLanguageSettingsKey, saved);
        QString error = "stale";
        QCOMPARE(chooseLanguage(commandLine, settings, QLocale(system), &error), expected);
        QCOMPARE(!error.isEmpty(), warns);
        if (warns)
            QVERIFY2(error.contains(commandLine.isEmpty() ? saved : commandLine),
                     qPrintable(error));
    }

    void everyMessageIsTranslated_data() {
        QTest::addColumn<QString>("code");
        QTest::newRow("de") << "de";
        QTest::newRow("fr") << "fr";
    }
    void everyMessageIsTranslated() {
        QFETCH(QString, code);
        QString language, error;
        const QList<TsMessage> messages = readTs(tsPath(code), language, error);
        QVERIFY2(error.isEmpty(), qPrintable(error));
        QCOMPARE(language, code);
        QVERIFY(messages.size() > 40);
        QStringList problems;
        for (const TsMessage& m : messages) {
            if (m.type == QLatin1String("vanished") || m.type == QLatin1String("obsolete"))
                continue;
            const QString where = m.context + " \"" + m.source + "\": ";
            if (m.type == QLatin1String("unfinished"))
                problems << where + "unfinished";
            if (m.translations.isEmpty() || (m.numerus && m.translations.size() < 2))
                problems << where + "missing translation or numerus forms";
            for (const QString& t : m.translations) {
                if (t.trimmed().isEmpty())
                    problems << where + "empty translation";
                else if (placeholders(t) != placeholders(m.source))
                    problems << where + "placeholders differ in \"" + t + "\"";
                else if (accelerators(t) != accelerators(m.source))
                    problems << where + "'&' accelerators differ in \"" + t + "\"";
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(tsPath(code) + ":\n  " + problems.join("\n  ")));
    }

    void translationFilesAreCurrent() {
        // lupdate into a scratch copy of each .ts: it must find nothing new and nothing gone.
        const QString lupdate = QStringLiteral(RESECT_LUPDATE);
        // tools/setup.sh installs it (qt6-l10n-tools); without it this check proves nothing.
        QVERIFY2(QFile::exists(lupdate), qPrintable(lupdate + " not found (Debian: qt6-l10n-tools)"));
        for (const QString code : {"de", "fr"}) {
            QTemporaryDir dir;
            const QString scratch = dir.filePath("scratch.ts");
            QVERIFY(QFile::copy(tsPath(code), scratch));
            QProcess p;
            p.setWorkingDirectory(RESECT_SOURCE_DIR);
            p.start(lupdate,
                    {"-I", ".", "-no-obsolete", "-locations", "none", "-source-language", "en",
                     "-target-language", code, "widgets", "app/studio", "-ts", scratch});
            QVERIFY(p.waitForFinished(120'000));
            QCOMPARE(p.exitCode(), 0);
            QString language, error;
            QSet<QString> current, checkedIn;
            for (const TsMessage& m : readTs(scratch, language, error))
                current << m.context + "|" + m.source;
            for (const TsMessage& m : readTs(tsPath(code), language, error))
                if (m.type != QLatin1String("vanished") && m.type != QLatin1String("obsolete"))
                    checkedIn << m.context + "|" + m.source;
            QStringList added = (current - checkedIn).values(),
                        gone = (checkedIn - current).values();
            added.sort();
            gone.sort();
            QVERIFY2(
                added.isEmpty() && gone.isEmpty(),
                qPrintable(
                    "translations/resect_studio_" + code +
                    ".ts is out of date: run tools/update_translations.sh and translate.\n  new: " +
                    added.join("\n       ") + "\n  gone: " + gone.join("\n        ")));
        }
    }
};

QTEST_MAIN(TestLanguage)
#include "test_language.moc"
