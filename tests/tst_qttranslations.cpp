// Tests that Qt's own strings (standard buttons, file dialogs) are translated with ServoBench's:
// the system's qtbase translations (Debian: qt6-translations-l10n, which ./setup.sh installs)
// are found and installed for Chinese and German, and none for English.
#include "translations.h"

#include <QDir>
#include <QLibraryInfo>
#include <QTranslator>
#include <QtTest>

class TestQtTranslations : public QObject
{
    Q_OBJECT

private:
    // The files of the installed translators, Qt's and ServoBench's.
    static QStringList installedFiles()
    {
        QStringList files;
        for (const QTranslator *translator :
             QCoreApplication::instance()->findChildren<QTranslator *>())
            files.append(QFileInfo(translator->filePath()).fileName());
        return files;
    }

    static QString qtTranslationFile(const QString &language)
    {
        return QDir(QLibraryInfo::path(QLibraryInfo::TranslationsPath))
            .filePath(QStringLiteral("qtbase_%1.qm").arg(language));
    }

private slots:
    void cleanup()
    {
        for (QTranslator *translator :
             QCoreApplication::instance()->findChildren<QTranslator *>()) {
            QCoreApplication::removeTranslator(translator);
            delete translator;
        }
    }

    void qtsTranslationsAreInstalled_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<QString>("cancel");
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN") << QStringLiteral("取消");
        QTest::newRow("de") << QStringLiteral("de") << QStringLiteral("Abbrechen");
    }

    void qtsTranslationsAreInstalled()
    {
        QFETCH(QString, language);
        QFETCH(QString, cancel);
        // ./setup.sh installs qt6-translations-l10n, and the Debian package depends on it.
        QVERIFY2(QFile::exists(qtTranslationFile(language)),
                 qPrintable(qtTranslationFile(language)
                            + QStringLiteral(" is missing: install qt6-translations-l10n")));
        QCOMPARE(util::installTranslations(language).name().left(2), language.left(2));
        QVERIFY2(installedFiles().contains(QStringLiteral("qtbase_%1.qm").arg(language)),
                 qPrintable(installedFiles().join(u',')));
        // What a QDialogButtonBox's Cancel shows.
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), cancel);
    }

    void englishInstallsNoQtTranslation()
    {
        util::installTranslations(QStringLiteral("en"));
        QVERIFY2(installedFiles().isEmpty(), qPrintable(installedFiles().join(u',')));
        QCOMPARE(QCoreApplication::translate("QPlatformTheme", "Cancel"), QStringLiteral("Cancel"));
    }
};

QTEST_GUILESS_MAIN(TestQtTranslations)
#include "tst_qttranslations.moc"
