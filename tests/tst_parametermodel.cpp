// Tests the shared parameter model: polls never overwrite edits; writes settle by read-back.
#include "parametermodel.h"

#include <QSignalSpy>
#include <QtTest>

using model::State;

namespace {

QVector<model::Definition> definitions()
{
    model::Definition gain;
    gain.key = QStringLiteral("gain");
    gain.label = QStringLiteral("Gain");
    gain.minimum = 0;
    gain.maximum = 30;
    model::Definition pulse;
    pulse.key = QStringLiteral("min_pulse_us");
    pulse.label = QStringLiteral("Minimum pulse width");
    pulse.unit = QStringLiteral("µs");
    pulse.scale = 0.25; // the wire carries µs × 4
    pulse.minimum = 2000;
    pulse.maximum = 6000;
    model::Definition voltage;
    voltage.key = QStringLiteral("present_voltage");
    voltage.label = QStringLiteral("Present voltage");
    voltage.access = model::Access::ReadOnly;
    voltage.maximum = 255;
    return {gain, pulse, voltage};
}

} // namespace

class TestParameterModel : public QObject
{
    Q_OBJECT

private slots:
    void aPollDuringAnEditLeavesTheEditAlone()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 20));
        parameters.setDeviceValue(QStringLiteral("gain"), 28, 1234);
        QCOMPARE(parameters.pendingValue(QStringLiteral("gain")).value_or(-1), 20);
        QCOMPARE(parameters.deviceValue(QStringLiteral("gain")).value_or(-1), 28);
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Edited);
        QCOMPARE(parameters.lastReadMs(QStringLiteral("gain")), 1234);
    }

    void outOfRangeAndReadOnlyEditsAreRefusedWithAReason()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        QString error;
        QVERIFY(!parameters.edit(QStringLiteral("gain"), 31, &error));
        QVERIFY(error.contains(QStringLiteral("between 0 and 30")));
        QVERIFY(!parameters.editScaled(QStringLiteral("min_pulse_us"), 499, &error));
        QVERIFY(error.contains(QStringLiteral("500 µs")));
        QVERIFY(!parameters.edit(QStringLiteral("present_voltage"), 70, &error));
        QVERIFY(!parameters.edit(QStringLiteral("nope"), 1, &error));
        QVERIFY(!parameters.editScaled(QStringLiteral("gain"), qQNaN(), &error));
        QVERIFY(!parameters.hasEdits());
    }

    void scaledEditsAreStoredInDeviceUnits()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        QVERIFY(parameters.editScaled(QStringLiteral("min_pulse_us"), 900));
        QCOMPARE(parameters.pendingValue(QStringLiteral("min_pulse_us")).value_or(-1), 3600);
        const QModelIndex pending = parameters.index(1, model::ParameterModel::PendingColumn);
        QCOMPARE(parameters.data(pending).toString(), QStringLiteral("900 µs"));
    }

    void typingTheDeviceValueBackIsNoEdit()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 10));
        QVERIFY(parameters.edit(QStringLiteral("gain"), 29));
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Clean);
        QVERIFY(!parameters.hasEdits());
    }

    void aWriteSettlesAsVerifiedOrMismatchByTheReadBack()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        parameters.setDeviceValue(QStringLiteral("min_pulse_us"), 2000);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 20));
        QVERIFY(parameters.editScaled(QStringLiteral("min_pulse_us"), 600));
        const QVector<model::WriteItem> plan = parameters.takeWritePlan();
        QCOMPARE(plan.size(), 2);
        QCOMPARE(plan[0].key, QStringLiteral("gain"));
        QCOMPARE(plan[0].value, 20);
        QCOMPARE(plan[1].value, 2400);
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Writing);
        QVERIFY(!parameters.hasEdits());

        parameters.setDeviceValue(QStringLiteral("gain"), 20);
        parameters.setDeviceValue(QStringLiteral("min_pulse_us"), 2000); // the servo ignored it
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Verified);
        QCOMPARE(parameters.state(QStringLiteral("min_pulse_us")), State::Mismatch);
        // Later polls do not undo the verdict.
        parameters.setDeviceValue(QStringLiteral("gain"), 20);
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Verified);
    }

    void keysKeptOutOfTheWritePlanStayEdits()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 20));
        QVERIFY(parameters.editScaled(QStringLiteral("min_pulse_us"), 600));
        const auto plan = parameters.takeWritePlan({QStringLiteral("min_pulse_us")});
        QCOMPARE(plan.size(), 1);
        QCOMPARE(plan[0].key, QStringLiteral("gain"));
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Writing);
        QCOMPARE(parameters.state(QStringLiteral("min_pulse_us")), State::Edited);
        QCOMPARE(parameters.pendingValue(QStringLiteral("min_pulse_us")).value_or(-1), 2400);
    }

    void aFailedWriteKeepsTheEditToTryAgain()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        QVERIFY(parameters.edit(QStringLiteral("gain"), 5));
        QCOMPARE(parameters.takeWritePlan().size(), 1);
        parameters.markFailed(QStringLiteral("gain"));
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Failed);
        QCOMPARE(parameters.pendingValue(QStringLiteral("gain")).value_or(-1), 5);
        QCOMPARE(parameters.takeWritePlan().size(), 1);
    }

    void anUnknownWriteIsSettledVerifiedByAReadThatShowsIt()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 3);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 5));
        QCOMPARE(parameters.takeWritePlan().size(), 1);
        parameters.markUnknown(QStringLiteral("gain"));
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Unknown);
        QCOMPARE(parameters.pendingValue(QStringLiteral("gain")).value_or(-1), 5);
        QVERIFY(!model::ParameterModel::stateName(State::Unknown).isEmpty());
        parameters.setDeviceValue(QStringLiteral("gain"), 5);
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Verified);
        QVERIFY(!parameters.pendingValue(QStringLiteral("gain")));
        QVERIFY(!parameters.hasEdits());
    }

    void anUnknownWriteIsSettledFailedByAReadThatShowsTheOldValue()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        parameters.setDeviceValue(QStringLiteral("gain"), 3);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 5));
        QCOMPARE(parameters.takeWritePlan().size(), 1);
        parameters.markUnknown(QStringLiteral("gain"));
        parameters.setDeviceValue(QStringLiteral("gain"), 3);
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Failed);
        QCOMPARE(parameters.pendingValue(QStringLiteral("gain")).value_or(-1), 5);
        QCOMPARE(parameters.takeWritePlan().size(), 1); // to try again
    }

    void revertDropsEditsAndTellsTheViews()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        QSignalSpy changes(&parameters, &QAbstractItemModel::dataChanged);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 5));
        QVERIFY(parameters.editScaled(QStringLiteral("min_pulse_us"), 700));
        parameters.revertAll();
        QVERIFY(!parameters.hasEdits());
        QCOMPARE(parameters.state(QStringLiteral("gain")), State::Clean);
        QVERIFY(changes.size() >= 4);
    }

    void theTableShowsKeysValuesAndStates()
    {
        model::ParameterModel parameters;
        parameters.setDefinitions(definitions());
        QCOMPARE(parameters.rowCount(), 3);
        QCOMPARE(parameters.columnCount(), int(model::ParameterModel::ColumnCount));
        parameters.setDeviceValue(QStringLiteral("gain"), 29);
        QVERIFY(parameters.edit(QStringLiteral("gain"), 3));
        QCOMPARE(
            parameters.data(parameters.index(0, model::ParameterModel::DeviceColumn)).toString(),
            QStringLiteral("29"));
        QCOMPARE(
            parameters.data(parameters.index(0, model::ParameterModel::StateColumn)).toString(),
            QStringLiteral("Edited"));
        QCOMPARE(
            parameters.data(parameters.index(0, 0), model::ParameterModel::RawPendingRole).toInt(),
            3);
    }
};

QTEST_GUILESS_MAIN(TestParameterModel)
#include "tst_parametermodel.moc"
