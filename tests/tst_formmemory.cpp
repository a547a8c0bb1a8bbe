// Tests what ServoBench remembers across runs: form values (widgetmemory), the Monitor's
// choices, and recent files by kind.
#include "monitorpage.h"
#include "recentfiles.h"
#include "widgetmemory.h"

#include <QCheckBox>
#include <QComboBox>
#include <QSettings>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

namespace {

// A spin box, a check box and a combo box that remember their values.
struct RememberedForm
{
    QSpinBox spin;
    QCheckBox check;
    QComboBox combo;

    RememberedForm()
    {
        spin.setRange(0, 253);
        combo.addItem(QStringLiteral("10 Hz"), 10.0);
        combo.addItem(QStringLiteral("50 Hz"), 50.0);
        widgetmemory::remember(&spin, QStringLiteral("test/spin"));
        widgetmemory::remember(&check, QStringLiteral("test/check"));
        widgetmemory::remember(&combo, QStringLiteral("test/combo"));
    }
};

} // namespace

class TestFormMemory : public QObject
{
    Q_OBJECT

private slots:
    void init() { QSettings().clear(); }

    void formValuesComeBack()
    {
        {
            RememberedForm form;
            form.spin.setValue(42);
            form.check.setChecked(true);
            form.combo.setCurrentIndex(1);
        }
        RememberedForm form;
        QCOMPARE(form.spin.value(), 42);
        QVERIFY(form.check.isChecked());
        QCOMPARE(form.combo.currentIndex(), 1);

        // A value the widget can no longer take is ignored, not forced.
        QSettings().setValue(QStringLiteral("test/small"), 900);
        QSpinBox small;
        small.setRange(0, 100);
        small.setValue(7);
        widgetmemory::remember(&small, QStringLiteral("test/small"));
        QCOMPARE(small.value(), 7);
    }

    void monitorChoicesComeBack()
    {
        {
            MonitorPage page(nullptr);
            auto *rate = page.findChild<QComboBox *>(QStringLiteral("monitorRateCombo"));
            auto *window = page.findChild<QComboBox *>(QStringLiteral("monitorWindowCombo"));
            auto *load = page.findChild<QCheckBox *>(QStringLiteral("plot_load"));
            auto *voltage = page.findChild<QCheckBox *>(QStringLiteral("plot_voltage"));
            QVERIFY(rate && window && load && voltage);
            rate->setCurrentIndex(0);
            window->setCurrentIndex(window->count() - 1);
            load->setChecked(false);
            voltage->setChecked(true);
        }
        MonitorPage page(nullptr);
        QCOMPARE(page.findChild<QComboBox *>(QStringLiteral("monitorRateCombo"))->currentIndex(),
                 0);
        auto *window = page.findChild<QComboBox *>(QStringLiteral("monitorWindowCombo"));
        QCOMPARE(window->currentIndex(), window->count() - 1);
        QVERIFY(!page.findChild<QCheckBox *>(QStringLiteral("plot_load"))->isChecked());
        QVERIFY(page.findChild<QCheckBox *>(QStringLiteral("plot_voltage"))->isChecked());
    }

    void recentFilesAreNewestFirstAndStillThere()
    {
        QTemporaryDir folder;
        QVERIFY(folder.isValid());
        QStringList files;
        for (int i = 0; i < recentfiles::kMaxFiles + 2; ++i) {
            const QString path = folder.filePath(QStringLiteral("profile-%1.json").arg(i));
            QFile file(path);
            QVERIFY(file.open(QIODevice::WriteOnly));
            files.append(path);
            recentfiles::add(recentfiles::Kind::Profile, path);
        }
        QStringList listed = recentfiles::list(recentfiles::Kind::Profile);
        QCOMPARE(listed.size(), recentfiles::kMaxFiles);
        QCOMPARE(listed.first(), files.last());
        QCOMPARE(recentfiles::directory(recentfiles::Kind::Profile), folder.path());
        // Opened again: back to the top, not listed twice.
        recentfiles::add(recentfiles::Kind::Profile, files.at(5));
        listed = recentfiles::list(recentfiles::Kind::Profile);
        QCOMPARE(listed.first(), files.at(5));
        QCOMPARE(listed.count(files.at(5)), 1);
        // A file deleted since is left out; the kinds are kept apart.
        QVERIFY(QFile::remove(files.at(5)));
        QVERIFY(!recentfiles::list(recentfiles::Kind::Profile).contains(files.at(5)));
        QVERIFY(recentfiles::list(recentfiles::Kind::Pose).isEmpty());
        // Nothing of a kind yet: Documents, or home where there is none; always a folder that
        // exists (a dialog given none opens wherever the last one was).
        const QString documents =
            QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation);
        QCOMPARE(recentfiles::directory(recentfiles::Kind::Pose),
                 QFileInfo(documents).isDir() ? documents : QDir::homePath());
        for (const auto kind :
             {recentfiles::Kind::PacketLog, recentfiles::Kind::ShareRecording,
              recentfiles::Kind::MotionRecording, recentfiles::Kind::PlotImage,
              recentfiles::Kind::HealthReport, recentfiles::Kind::TelemetryRecording})
            QVERIFY(QFileInfo(recentfiles::directory(kind)).isDir());
        // Each kind keeps its own folder: a packet log saved elsewhere moves only its own.
        QTemporaryDir logs;
        const QString log = logs.filePath(QStringLiteral("packets.tsv"));
        QFile logFile(log);
        QVERIFY(logFile.open(QIODevice::WriteOnly));
        logFile.close();
        recentfiles::add(recentfiles::Kind::PacketLog, log);
        QCOMPARE(recentfiles::directory(recentfiles::Kind::PacketLog), logs.path());
        QCOMPARE(recentfiles::directory(recentfiles::Kind::Profile), folder.path());
        QCOMPARE(recentfiles::suggestedPath(recentfiles::Kind::PacketLog, QStringLiteral("x.tsv")),
                 logs.filePath(QStringLiteral("x.tsv")));
    }
};

QTEST_MAIN(TestFormMemory)
#include "tst_formmemory.moc"
