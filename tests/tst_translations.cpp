// Tests that the German and Chinese translations are complete and well formed, cover the
// shipped tables' and templates' texts, and show on the window and a settings page under zh_CN.
#include "busclient.h"
#include "feetechdescription.h"
#include "feetechpacket.h"
#include "feetechworkspace.h"
#include "mainwindow.h"
#include "parameterpage.h"
#include "registertable.h"
#include "robottemplate.h"
#include "simulatordock.h"
#include "translations.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLabel>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSettings>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

namespace {

struct Message
{
    QString context;
    QString source;
    bool numerus = false;
    bool finished = false;
    QStringList forms; // one translation, or the numerus forms
};

// A language's file ("de"), or a .ts file by its path.
QVector<Message> readTs(const QString &language)
{
    QFile file(
        language.endsWith(QLatin1String(".ts"))
            ? language
            : QStringLiteral(SERVOBENCH_SOURCE_DIR "/resources/translations/servobench_%1.ts")
                  .arg(language));
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QVector<Message> messages;
    QXmlStreamReader xml(&file);
    QString context;
    Message message;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement())
            continue;
        const auto name = xml.name();
        if (name == u"name") {
            context = xml.readElementText();
        } else if (name == u"message") {
            if (!message.source.isNull())
                messages.append(message);
            message = Message {};
            message.context = context;
            message.numerus = xml.attributes().value(QLatin1String("numerus")) == u"yes";
        } else if (name == u"source") {
            message.source = xml.readElementText();
        } else if (name == u"translation") {
            const auto type = xml.attributes().value(QLatin1String("type"));
            message.finished = type.isEmpty();
            if (!message.numerus)
                message.forms.append(xml.readElementText());
        } else if (name == u"numerusform") {
            message.forms.append(xml.readElementText());
        }
    }
    if (!message.source.isNull())
        messages.append(message);
    return xml.hasError() ? QVector<Message> {} : messages;
}

// Placeholders and markup a translation must keep: %1, %L2, %n, <b>...
QStringList tokens(const QString &text, bool withCount)
{
    static const QRegularExpression pattern(QStringLiteral("%L?\\d+|%L?n|<[^>]+>"));
    QStringList found;
    for (auto match = pattern.globalMatch(text); match.hasNext();) {
        const QString token = match.next().captured();
        if (withCount || !token.endsWith(u'n'))
            found.append(token);
    }
    found.sort();
    return found;
}

// Every text of the shipped register tables and robot templates, as datastrings.cpp lists them.
QSet<QPair<QString, QString>> dataTexts()
{
    QSet<QPair<QString, QString>> texts;
    const auto add = [&texts](const char *context, const QString &text) {
        if (!text.isEmpty())
            texts.insert({QLatin1String(context), text});
    };
    for (const feetech::Family family : feetech::kAllFamilies) {
        const feetech::RegisterTable &table = feetech::RegisterTable::forFamily(family);
        add("FeetechRegister", table.title());
        for (const feetech::Register &reg : table.registers()) {
            add("FeetechRegister", reg.label);
            add("FeetechRegister", reg.note);
            add("FeetechRegister", reg.unit);
            for (const feetech::Choice &choice : reg.choices)
                add("FeetechRegister", choice.label);
            for (const feetech::BitName &bit : reg.bits)
                add("FeetechRegister", bit.label);
        }
    }
    for (const feetech::RobotTemplate &robot : feetech::availableRobotTemplates()) {
        add("RobotTemplate", robot.name);
        for (const feetech::RobotJoint &joint : robot.joints)
            add("Joint", joint.name);
    }
    return texts;
}

bool hasChinese(const QString &text)
{
    return std::any_of(text.begin(), text.end(),
                       [](QChar c) { return c.unicode() >= 0x4E00 && c.unicode() <= 0x9FFF; });
}

} // namespace

class TestTranslations : public QObject
{
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); } // nothing remembered from an earlier case

    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void everyMessageIsTranslated_data()
    {
        QTest::addColumn<QString>("language");
        QTest::addColumn<int>("forms");
        QTest::newRow("de") << QStringLiteral("de") << 2;
        QTest::newRow("zh_CN") << QStringLiteral("zh_CN") << 1;
    }

    void everyMessageIsTranslated()
    {
        QFETCH(QString, language);
        QFETCH(int, forms);
        const QVector<Message> messages = readTs(language);
        QVERIFY2(messages.size() > 1000, qPrintable(QString::number(messages.size())));
        QStringList problems;
        for (const Message &message : messages) {
            const QString where = message.context + QStringLiteral(": ") + message.source;
            if (!message.finished)
                problems.append(QStringLiteral("unfinished: ") + where);
            if (message.forms.size() != (message.numerus ? forms : 1)) {
                problems.append(QStringLiteral("wrong number of forms: ") + where);
                continue;
            }
            for (const QString &form : message.forms) {
                if (form.trimmed().isEmpty())
                    problems.append(QStringLiteral("empty: ") + where);
                else if (tokens(form, !message.numerus) != tokens(message.source, !message.numerus))
                    problems.append(QStringLiteral("placeholders differ: ") + where);
                if (form.count(u'\n') != message.source.count(u'\n'))
                    problems.append(QStringLiteral("line count differs: ") + where);
            }
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.mid(0, 20).join(u'\n')));
    }

    // lupdate over the sources, into a copy of each file: a string in the code that the file
    // lacks (nobody ran update_translations, or nobody translated it) shows as unfinished.
    void everyStringOfTheCodeIsInBothFiles()
    {
        QTemporaryDir scratch;
        QVERIFY(scratch.isValid());
        for (const QString &language : util::translatedLanguages()) {
            const QString name = QStringLiteral("servobench_%1.ts").arg(language);
            const QString copy = scratch.filePath(name);
            QVERIFY(QFile::copy(
                QStringLiteral(SERVOBENCH_SOURCE_DIR "/resources/translations/") + name, copy));
            QFile::setPermissions(copy, QFile::ReadOwner | QFile::WriteOwner);
            QProcess lupdate;
            lupdate.setProcessChannelMode(QProcess::MergedChannels);
            const QString source = QStringLiteral(SERVOBENCH_SOURCE_DIR);
            lupdate.start(QStringLiteral(SERVOBENCH_LUPDATE),
                          {QStringLiteral("-silent"), QStringLiteral("-no-obsolete"),
                           QStringLiteral("-locations"), QStringLiteral("none"),
                           QStringLiteral("-extensions"), QStringLiteral("cpp,h"),
                           source + QStringLiteral("/core"), source + QStringLiteral("/ui"),
                           source + QStringLiteral("/app"),
                           source + QStringLiteral("/resources/translations/datastrings.cpp"),
                           QStringLiteral("-ts"), copy});
            QVERIFY(lupdate.waitForFinished(120000));
            QVERIFY2(lupdate.exitCode() == 0, lupdate.readAll().constData());
            QStringList missing;
            for (const Message &message : readTs(copy)) {
                if (!message.finished)
                    missing.append(message.context + QStringLiteral(": ") + message.source);
            }
            // Run the update_translations target, then translate what it added.
            QVERIFY2(missing.isEmpty(),
                     qPrintable(language + QStringLiteral(" lacks:\n")
                                + missing.mid(0, 20).join(u'\n')));
        }
    }

    void tablesAndTemplatesAreInBothFiles()
    {
        const QSet<QPair<QString, QString>> wanted = dataTexts();
        QVERIFY(wanted.size() > 150);
        for (const QString &language : util::translatedLanguages()) {
            QSet<QPair<QString, QString>> present;
            for (const Message &message : readTs(language))
                present.insert({message.context, message.source});
            QStringList missing;
            for (const auto &text : wanted) {
                if (!present.contains(text))
                    missing.append(text.first + QStringLiteral(": ") + text.second);
            }
            // Run resources/translations/datastrings.py, then the update_translations target.
            QVERIFY2(missing.isEmpty(),
                     qPrintable(language + QStringLiteral(" lacks ") + missing.join(u'\n')));
        }
    }

    void windowAndSettingsPageShowChinese()
    {
        QCOMPARE(util::installTranslations(QStringLiteral("zh_CN")).name(),
                 QStringLiteral("zh_CN"));
        QCOMPARE(feetech::tableText(QStringLiteral("Max temperature")).isEmpty(), false);
        QVERIFY(hasChinese(feetech::tableText(QStringLiteral("Max temperature"))));
        QVERIFY(hasChinese(feetech::jointDisplayName(QStringLiteral("shoulder_pan"))));
        // The packet log names instructions as the Chinese manual does; its JSON keeps the
        // protocol's names.
        for (const QByteArray &frame : {feetech::ping(1), feetech::read(1, 56, 2)}) {
            const QString said = feetech::describeFrame(frame, {});
            QVERIFY2(hasChinese(said.section(u' ', 0, 0)), qPrintable(said));
        }
        QCOMPARE(*feetech::instructionName(quint8(feetech::Instruction::Ping)),
                 QStringLiteral("PING"));

        MainWindow window;
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        for (QAction *menu : window.menuBar()->actions())
            QVERIFY2(hasChinese(menu->text()), qPrintable(menu->text()));
        auto *state = window.findChild<QLabel *>(QStringLiteral("connectionState"));
        QVERIFY(state && hasChinese(state->text()));

        // The simulated bus, scanned: the first servo's settings page, its labels in Chinese.
        window.startFeetechDemo();
        feetech::BusClient *client = window.feetechClient();
        QTRY_VERIFY_WITH_TIMEOUT(
            window.feetechWorkspace()->currentIndex() >= 0
                && client->servos()->at(window.feetechWorkspace()->currentIndex()).read,
            15000);
        ParameterPage *settings = window.feetechWorkspace()->settingsPage();
        QStringList texts;
        for (QLabel *label : settings->findChildren<QLabel *>())
            texts.append(label->text());
        QVERIFY2(texts.contains(feetech::tableText(QStringLiteral("Max temperature"))),
                 qPrintable(texts.join(u'|')));
        // Chinese text is taller: the window, with the Feetech pages and the Simulator dock, still
        // fits what a 1366x768 screen leaves under a desktop's panel and a title bar (some 70
        // pixels).
        QVERIFY(window.simulatorDock() && window.simulatorDock()->isVisible());
        QVERIFY2(window.minimumSizeHint().height() <= 700,
                 qPrintable(QString::number(window.minimumSizeHint().height())));
    }
};

QTEST_MAIN(TestTranslations)
#include "tst_translations.moc"
