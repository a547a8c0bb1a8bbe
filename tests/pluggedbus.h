// Test support for motor set-up: servos plugged into and out of the running simulated bus, and
// what their EEPROMs hold.
#pragma once

#include "feetechbus.h"
#include "robottemplate.h"

#include <QtTest>

namespace testsupport {

constexpr qint32 kFactoryBaud = 1000000; // a factory-new STS3215: ID 1 at 1 Mbps

// A simulated servo as the test sees it from outside the bus.
struct PluggedServo
{
    quint8 id = 0;
    qint32 baud = 0;
    QString model;
    quint64 revision = 0; // counts the EEPROM writes
    QByteArray eeprom;
};

// The built-in template named `name` ("SO-101 follower arm").
inline feetech::RobotTemplate builtInRobot(const QString &name)
{
    for (const feetech::RobotTemplate &robot : feetech::builtInRobotTemplates()) {
        if (robot.name == name)
            return robot;
    }
    qWarning("no built-in robot template \"%s\"", qPrintable(name));
    return {};
}

// Base of a test object whose tests plug servos into a simulated bus that starts empty.
class PluggedBusTest : public FeetechBusTest
{
protected:
    // The simulator wants a servo to start with: one is plugged in and out again.
    bool startEmptyBus(QString *error)
    {
        if (!startSimulator(busOptions({{1, QStringLiteral("STS3215"), kFactoryBaud}}), error))
            return false;
        unplugAll();
        return true;
    }

    // Plugs a powered-up servo in (last in the bus's order); false and a warning when refused.
    bool plug(quint8 id, const QString &model, qint32 baud)
    {
        sim::SimRefusal why;
        bool plugged = false;
        m_simulator->call([&](sim::Simulator &simulator) {
            plugged = simulator.feetechBus()->plug({id, model, baud}, &why);
        });
        if (!plugged)
            qWarning("could not plug %s at ID %d: %s", qPrintable(model), id,
                     qPrintable(why.describe()));
        return plugged;
    }

    void unplugAll()
    {
        m_simulator->call([](sim::Simulator &simulator) {
            while (simulator.feetechBus()->servoCount() > 0)
                simulator.feetechBus()->unplug(0);
        });
    }

    void powerCycle()
    {
        m_simulator->call([](sim::Simulator &simulator) { simulator.powerCycle(); });
    }

    // Every servo on the bus, in its order.
    QVector<PluggedServo> pluggedServos()
    {
        QVector<PluggedServo> servos;
        m_simulator->call([&](sim::Simulator &simulator) {
            sim::VirtualFeetechBus &bus = *simulator.feetechBus();
            for (int i = 0; i < bus.servoCount(); ++i) {
                const sim::VirtualFeetechServo &servo = bus.servo(i);
                servos.append({servo.id(), servo.baudRate(), servo.model().name,
                               servo.eepromRevision(), servo.eepromImage()});
            }
        });
        return servos;
    }

    // Register `key` of the servo at `index` of the bus; -1 without that servo.
    qint32 pluggedValue(int index, QStringView key)
    {
        qint32 value = -1;
        m_simulator->call([&](sim::Simulator &simulator) {
            sim::VirtualFeetechBus &bus = *simulator.feetechBus();
            if (index < bus.servoCount())
                value = bus.servo(index).value(key);
        });
        return value;
    }

    // Fails the test unless the servo at `index` answers as `joint` of `robot` should: its ID,
    // the template's rate, and every setting of the joint (after a power cycle only those kept
    // in EEPROM: a RAM register such as acceleration starts from its default again).
    enum class Settings { All, EepromOnly };
    void verifySetUp(int index, const feetech::RobotTemplate &robot,
                     const feetech::RobotJoint &joint, Settings which = Settings::All)
    {
        const QVector<PluggedServo> servos = pluggedServos();
        QVERIFY(index < servos.size());
        QCOMPARE(servos.at(index).id, quint8(joint.id));
        QCOMPARE(servos.at(index).baud, robot.baud);
        QVERIFY(!joint.settings.isEmpty());
        const feetech::RegisterTable &table =
            feetech::RegisterTable::forFamily(feetech::Family::Sts);
        int eeprom = 0;
        for (auto it = joint.settings.cbegin(); it != joint.settings.cend(); ++it) {
            const feetech::Register *reg = table.find(it.key());
            QVERIFY(reg);
            const bool kept = reg->storage == feetech::Storage::Eeprom;
            eeprom += kept ? 1 : 0;
            if (which == Settings::All || kept)
                QCOMPARE(pluggedValue(index, it.key()), it.value());
        }
        QVERIFY(eeprom > 0);
        QCOMPARE(pluggedValue(index, u"lock"), 1); // locked again
    }
};

} // namespace testsupport
