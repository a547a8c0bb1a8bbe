// The fixture of the servoctl feetech tests: a simulated mixed bus over a pty with a frame log,
// servoctl run in-process against it, and what the bus received.
#pragma once

#include "servoctlrun.h"
#include "simclient.h"

#include "profile.h"
#include "robottemplate.h"
#include "servoparameters.h"
#include "simulatorthread.h"
#include "telemetry.h"
#include "virtualfeetechservo.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

namespace servoctlfeetech {

constexpr qint32 k1M = 1000000;
constexpr qint32 k115k = 115200;
constexpr quint8 kWrite = 0x03;
constexpr quint8 kRecovery = 0x06;

inline QJsonObject objectOf(const QString &json)
{
    return QJsonDocument::fromJson(json.toUtf8()).object();
}

inline QJsonObject byId(const QJsonArray &servos, int id)
{
    for (const QJsonValue &servo : servos) {
        if (servo[QStringLiteral("id")].toInt() == id)
            return servo.toObject();
    }
    return {};
}

inline QJsonObject registerNamed(const QJsonObject &read, const QString &key)
{
    for (const QJsonValue &reg : read.value(QStringLiteral("registers")).toArray()) {
        if (reg[QStringLiteral("key")].toString() == key)
            return reg.toObject();
    }
    return {};
}

class ServoctlFeetechBus
{
public:
    QTemporaryDir m_dir;
    sim::SimulatorThread m_simulator;
    QString m_logPath;

    // `arguments` after "servoctl --port LINK feetech".
    QStringList feetech(const QStringList &arguments) const
    {
        return QStringList {QStringLiteral("--port"), m_simulator.linkPath(),
                            QStringLiteral("feetech")}
        + arguments;
    }

    testsupport::ServoctlResult run(const QString &line) const
    {
        return testsupport::runServoctl(feetech(line.split(u' ', Qt::SkipEmptyParts)));
    }

    QStringList framesReceived() const
    {
        return testsupport::logLinesStartingWith(m_logPath, QStringLiteral("in "));
    }

    // The instruction byte of every frame the bus received.
    QVector<quint8> instructionsReceived() const
    {
        QVector<quint8> instructions;
        for (const QString &line : framesReceived()) {
            const QString hex = line.mid(3).section(QStringLiteral("  #"), 0, 0).trimmed();
            const auto frame = util::parseHex(hex);
            if (frame && frame->size() > 4)
                instructions.append(quint8(frame->at(4)));
        }
        return instructions;
    }

    int writesReceived() const { return int(instructionsReceived().count(kWrite)); }

    qint32 servoValue(quint8 id, const QString &key)
    {
        qint32 value = 0;
        m_simulator.call(
            [&](sim::Simulator &s) { value = s.feetechBus()->findServo(id)->value(key); });
        return value;
    }

    void setServoValue(quint8 id, const QString &key, qint32 value)
    {
        m_simulator.call(
            [&](sim::Simulator &s) { s.feetechBus()->findServo(id)->setValue(key, value); });
    }

    // The mixed bus: STS3215 at 1 and 2, SCS15 at 3 (1 Mbps), an SMS at 5 (115200).
    void start()
    {
        start({{1, QStringLiteral("STS3215"), k1M},
               {2, QStringLiteral("STS3215"), k1M},
               {3, QStringLiteral("SCS15"), k1M},
               {5, QStringLiteral("SMS"), k115k}});
    }

    void start(const QVector<sim::FeetechServoSpec> &servos, bool sharedIds = false)
    {
        QVERIFY(m_dir.isValid());
        static int run = 0;
        sim::SimulatorOptions options;
        options.kind = sim::SimulatorOptions::Kind::Feetech;
        options.linkPath = m_dir.filePath(QStringLiteral("bus%1").arg(++run));
        m_logPath = options.linkPath + QStringLiteral(".log");
        options.logPath = m_logPath;
        options.echo = run % 2 == 0; // every other test through a single-wire adapter
        options.instant = testsupport::instantTestDevice();
        options.servos = servos;
        options.allowSharedIds = sharedIds;
        QString error;
        QVERIFY2(m_simulator.start(options, &error), qPrintable(error));
    }

    void stop() { m_simulator.stop(); }

    // What the running simulator was started with, the servos aside: a bus of other servos.
    void restart(const QVector<sim::FeetechServoSpec> &servos, bool sharedIds = false)
    {
        stop();
        start(servos, sharedIds);
    }

    void setSupplyVoltage(double volts)
    {
        m_simulator.call([volts](sim::Simulator &s) { s.feetechBus()->setSupplyVoltage(volts); });
    }
};

} // namespace servoctlfeetech
