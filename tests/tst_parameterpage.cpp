// Tests the PTK page: device values beside edits, edits reach the model, polls never overwrite.
#include "parametermodel.h"
#include "parameterpage.h"
#include "ptkparameters.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QGroupBox>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

using model::State;

namespace {

// What a first read of the seed's sample servo leaves in the model.
void readSampleServo(model::ParameterModel &parameters)
{
    const ptk::ParameterSet sample = ptk::ParameterSet::seedSample(true);
    for (const ptk::ParameterInfo &info : ptk::parameterInfos())
        parameters.setDeviceValue(QLatin1String(info.key), *sample.value(info.parameter));
}

QString key(const char *name)
{
    return QLatin1String(name);
}

// Replaces the text of a spin box the way a user does: select all, then type.
void typeInto(QAbstractSpinBox *spin, const QString &text)
{
    spin->selectAll();
    QTest::keyClicks(spin, text);
}

} // namespace

class TestParameterPage : public QObject
{
    Q_OBJECT

private slots:
    void withoutAModelItShowsItsEmptyStateText()
    {
        ParameterPage::Options options;
        options.emptyText = QStringLiteral("No servo chosen.");
        ParameterPage page(nullptr, options);
        auto *empty = page.findChild<QLabel *>(QStringLiteral("emptyState"));
        QVERIFY(empty);
        QCOMPARE(empty->text(), options.emptyText);
        // Given a model, the form replaces it.
        page.setModel(m_parameters.get());
        QVERIFY(!page.findChild<QLabel *>(QStringLiteral("emptyState")));
    }

    void init()
    {
        m_parameters = std::make_unique<model::ParameterModel>();
        m_parameters->setDefinitions(ptk::modelDefinitions());
        m_page = std::make_unique<ParameterPage>(m_parameters.get());
    }

    void cleanup()
    {
        m_page.reset();
        m_parameters.reset();
    }

    void theGroupsFollowTheDefinitionsInOrder()
    {
        QStringList titles;
        for (const QGroupBox *box : m_page->findChildren<QGroupBox *>())
            titles.append(box->title());
        QCOMPARE(titles, (QStringList {key("Response"), key("Travel"), key("Power")}));
        for (const ptk::ParameterInfo &info : ptk::parameterInfos()) {
            QWidget *editor = m_page->editor(key(info.key));
            QVERIFY2(editor, info.key);
            QCOMPARE(editor->objectName(), QStringLiteral("editor_") + key(info.key));
            QVERIFY(!editor->toolTip().isEmpty());
        }
        QVERIFY(qobject_cast<QSpinBox *>(m_page->editor(key("gain"))));
        QVERIFY(qobject_cast<QComboBox *>(m_page->editor(key("inversion"))));
        auto *pulse = qobject_cast<QDoubleSpinBox *>(m_page->editor(key("min_pulse_us")));
        QVERIFY(pulse);
        QCOMPARE(pulse->decimals(), 2);
        QCOMPARE(pulse->minimum(), 500.0);
        QCOMPARE(pulse->maximum(), 1500.0);
        QCOMPARE(pulse->singleStep(), 1.0);
        QVERIFY(pulse->toolTip().contains(QStringLiteral("500 to 1500 µs")));
    }

    void editorsAreDisabledUntilTheirFirstRead()
    {
        for (const ptk::ParameterInfo &info : ptk::parameterInfos())
            QVERIFY2(!m_page->editor(key(info.key))->isEnabled(), info.key);
        QCOMPARE(m_page->deviceLabel(key("gain"))->text(), QStringLiteral("—"));

        m_parameters->setDeviceValue(key("gain"), 29);
        QVERIFY(m_page->editor(key("gain"))->isEnabled());
        QVERIFY(!m_page->editor(key("damping"))->isEnabled());
    }

    void deviceLabelsShowValuesInUserUnits()
    {
        readSampleServo(*m_parameters);
        QCOMPARE(m_page->deviceLabel(key("gain"))->text(), QStringLiteral("29"));
        QCOMPARE(m_page->deviceLabel(key("min_pulse_us"))->text(), QStringLiteral("500 µs"));
        QCOMPARE(m_page->deviceLabel(key("max_pulse_us"))->text(), QStringLiteral("2500 µs"));
        QCOMPARE(m_page->deviceLabel(key("overload_time_ms"))->text(), QStringLiteral("2000 ms"));
        QCOMPARE(m_page->deviceLabel(key("inversion"))->text(), QStringLiteral("On"));
        auto *pulse = qobject_cast<QDoubleSpinBox *>(m_page->editor(key("min_pulse_us")));
        QCOMPARE(pulse->value(), 500.0);
        auto *inversion = qobject_cast<QComboBox *>(m_page->editor(key("inversion")));
        QCOMPARE(inversion->currentText(), QStringLiteral("On"));
        QVERIFY(!m_parameters->hasEdits()); // showing device values made no edits
    }

    void typingIntoAnEditorMakesAnEdit()
    {
        readSampleServo(*m_parameters);
        auto *gain = qobject_cast<QSpinBox *>(m_page->editor(key("gain")));
        typeInto(gain, QStringLiteral("25"));
        QCOMPARE(m_parameters->pendingValue(key("gain")).value_or(-1), 25);
        QCOMPARE(m_parameters->state(key("gain")), State::Edited);
        QCOMPARE(m_page->stateLabel(key("gain"))->text(), QStringLiteral("Edited"));
        QVERIFY(m_page->stateLabel(key("gain"))->font().bold());
        QVERIFY(gain->palette().color(QPalette::Base)
                != m_page->editor(key("damping"))->palette().color(QPalette::Base));

        auto *pulse = qobject_cast<QDoubleSpinBox *>(m_page->editor(key("min_pulse_us")));
        typeInto(pulse, QStringLiteral("900"));
        QCOMPARE(m_parameters->pendingValue(key("min_pulse_us")).value_or(-1), 3600);

        auto *inversion = qobject_cast<QComboBox *>(m_page->editor(key("inversion")));
        inversion->setCurrentIndex(inversion->findText(QStringLiteral("Off")));
        QCOMPARE(m_parameters->pendingValue(key("inversion")).value_or(-1), 0);
    }

    void aLaterPollLeavesTheEditAndTheEditorAlone()
    {
        readSampleServo(*m_parameters);
        auto *gain = qobject_cast<QSpinBox *>(m_page->editor(key("gain")));
        typeInto(gain, QStringLiteral("25"));
        m_parameters->setDeviceValue(key("gain"), 20);
        QCOMPARE(gain->text(), QStringLiteral("25"));
        QCOMPARE(m_parameters->pendingValue(key("gain")).value_or(-1), 25);
        QCOMPARE(m_page->deviceLabel(key("gain"))->text(), QStringLiteral("20"));
    }

    void aPollWhileTypingTheDeviceValueDoesNotRewriteTheField()
    {
        m_page->show();
        m_page->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_page.get()));
        readSampleServo(*m_parameters);
        auto *gain = qobject_cast<QSpinBox *>(m_page->editor(key("gain")));
        gain->setFocus();
        QTRY_VERIFY(gain->hasFocus());

        // Typing the servo's own value back is no edit, so nothing pending protects the field.
        typeInto(gain, QStringLiteral("29"));
        QVERIFY(!m_parameters->pendingValue(key("gain")));
        m_parameters->setDeviceValue(key("gain"), 28);
        QCOMPARE(gain->text(), QStringLiteral("29"));

        // Leaving the field makes what it shows the edit.
        m_page->findChild<QPushButton *>(QStringLiteral("loadProfileButton"))->setFocus();
        QTRY_VERIFY(!gain->hasFocus());
        QCOMPARE(m_parameters->pendingValue(key("gain")).value_or(-1), 29);
        QCOMPARE(gain->text(), QStringLiteral("29"));
    }

    void revertRestoresTheDeviceValueAndClearsTheState()
    {
        readSampleServo(*m_parameters);
        auto *gain = qobject_cast<QSpinBox *>(m_page->editor(key("gain")));
        typeInto(gain, QStringLiteral("25"));
        auto *revert = m_page->findChild<QPushButton *>(QStringLiteral("revertButton"));
        QVERIFY(revert->isEnabled());
        revert->click();
        QCOMPARE(gain->value(), 29);
        QVERIFY(!m_parameters->hasEdits());
        QCOMPARE(m_parameters->state(key("gain")), State::Clean);
        QCOMPARE(m_page->stateLabel(key("gain"))->text(), QString());
        QVERIFY(!revert->isEnabled());
    }

    void applyNeedsEditsAndALinkAndAsksForTheWrite()
    {
        auto *apply = m_page->findChild<QPushButton *>(QStringLiteral("applyButton"));
        auto *read = m_page->findChild<QPushButton *>(QStringLiteral("readButton"));
        QSignalSpy applied(m_page.get(), &ParameterPage::applyRequested);
        QSignalSpy readAsked(m_page.get(), &ParameterPage::readRequested);
        readSampleServo(*m_parameters);
        QVERIFY(!apply->isEnabled());
        QVERIFY(!read->isEnabled());

        m_page->setLinkReady(true);
        QVERIFY(read->isEnabled());
        QVERIFY(!apply->isEnabled()); // nothing to write yet
        typeInto(qobject_cast<QSpinBox *>(m_page->editor(key("gain"))), QStringLiteral("25"));
        QVERIFY(apply->isEnabled());
        m_page->setLinkReady(false);
        QVERIFY(!apply->isEnabled());
        m_page->setLinkReady(true);

        apply->click();
        read->click();
        QCOMPARE(applied.size(), 1);
        QCOMPARE(readAsked.size(), 1);
    }

    void profileButtonsAskTheWindow()
    {
        QSignalSpy save(m_page.get(), &ParameterPage::saveProfileRequested);
        QSignalSpy load(m_page.get(), &ParameterPage::loadProfileRequested);
        m_page->findChild<QPushButton *>(QStringLiteral("saveProfileButton"))->click();
        m_page->findChild<QPushButton *>(QStringLiteral("loadProfileButton"))->click();
        QCOMPARE(save.size(), 1);
        QCOMPARE(load.size(), 1);
    }

    void aWriteShowsWritingThenVerifiedFromTheReadBack()
    {
        readSampleServo(*m_parameters);
        typeInto(qobject_cast<QSpinBox *>(m_page->editor(key("gain"))), QStringLiteral("20"));
        typeInto(qobject_cast<QSpinBox *>(m_page->editor(key("damping"))), QStringLiteral("30"));
        QCOMPARE(m_parameters->takeWritePlan().size(), 2);
        QCOMPARE(m_page->stateLabel(key("gain"))->text(), QStringLiteral("Writing…"));

        m_parameters->setDeviceValue(key("gain"), 20);
        m_parameters->setDeviceValue(key("damping"), 12); // the servo kept its old value
        QCOMPARE(m_page->stateLabel(key("gain"))->text(), QStringLiteral("✓ Verified"));
        QCOMPARE(m_page->stateLabel(key("damping"))->text(), QStringLiteral("✗ Mismatch"));
        QCOMPARE(qobject_cast<QSpinBox *>(m_page->editor(key("gain")))->value(), 20);
        QCOMPARE(qobject_cast<QSpinBox *>(m_page->editor(key("damping")))->value(), 12);
        QVERIFY(m_page->stateLabel(key("gain"))->palette().color(QPalette::WindowText)
                != m_page->stateLabel(key("damping"))->palette().color(QPalette::WindowText));
    }

    void busyDisablesEditorsAndButtonsAndShowsProgress()
    {
        readSampleServo(*m_parameters);
        m_page->setLinkReady(true);
        typeInto(qobject_cast<QSpinBox *>(m_page->editor(key("gain"))), QStringLiteral("20"));
        m_page->show();
        QVERIFY(QTest::qWaitForWindowExposed(m_page.get()));

        m_page->setBusy(true, QStringLiteral("Writing N3"));
        m_page->setProgress(3, 12);
        QVERIFY(!m_page->editor(key("gain"))->isEnabled());
        for (const char *name : {"readButton", "applyButton", "revertButton", "saveProfileButton",
                                 "loadProfileButton"})
            QVERIFY2(!m_page->findChild<QPushButton *>(QLatin1String(name))->isEnabled(), name);
        auto *progress = m_page->findChild<QProgressBar *>();
        QVERIFY(progress->isVisible());
        QCOMPARE(progress->value(), 3);
        QCOMPARE(progress->maximum(), 12);
        auto *what = m_page->findChild<QLabel *>(QStringLiteral("busyLabel"));
        QVERIFY(what->isVisible());
        QCOMPARE(what->text(), QStringLiteral("Writing N3"));

        m_page->setBusy(false);
        QVERIFY(!progress->isVisible());
        QVERIFY(m_page->editor(key("gain"))->isEnabled());
        QVERIFY(m_page->findChild<QPushButton *>(QStringLiteral("applyButton"))->isEnabled());
    }

    void newDefinitionsRebuildTheForm()
    {
        readSampleServo(*m_parameters);
        QVector<model::Definition> one = ptk::modelDefinitions().mid(0, 1);
        m_parameters->setDefinitions(one);
        QVERIFY(m_page->editor(key("gain")));
        QVERIFY(!m_page->editor(key("damping")));
        QCOMPARE(m_page->findChildren<QGroupBox *>().size(), 1);
    }

private:
    std::unique_ptr<model::ParameterModel> m_parameters;
    std::unique_ptr<ParameterPage> m_page;
};

QTEST_MAIN(TestParameterPage)
#include "tst_parameterpage.moc"
