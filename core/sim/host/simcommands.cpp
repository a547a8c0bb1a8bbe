// servosim's standard-input commands: turn, sweep, release, plug, unplug, set-id, list,
// power-cycle, the bench cases (power, break-chain, supply, heat, temperature, block, unblock,
// latch) and help, each answered with one line.
#include "simcommands.h"

#include "hex.h"
#include "servosimtr.h"
#include "simulator.h"

#include <QCoreApplication>
#include <QHash>
#include <QRegularExpression>

#include <cmath>

namespace sim {

namespace {

QString ok(const QString &text)
{
    return QStringLiteral("ok ") + text;
}

QString error(const QString &text)
{
    return QStringLiteral("error ") + text;
}

QString place(const VirtualFeetechBus &bus, int index)
{
    return ServosimTr::tr("#%1 (ID %2)").arg(index + 1).arg(bus.servo(index).id());
}

QString listLine(const QVector<SimulatedServo> &servos)
{
    if (servos.isEmpty())
        return ServosimTr::tr("no servos");
    QStringList entries;
    for (const SimulatedServo &servo : servos) {
        entries.append(QStringLiteral("#%1 id=%2 baud=%3 model=%4 position=%5 torque=%6%7")
                           .arg(servo.index + 1)
                           .arg(servo.id)
                           .arg(servo.baud)
                           .arg(servo.model)
                           .arg(servo.position)
                           .arg(servo.torqueOn ? QLatin1String("on") : QLatin1String("off"))
                           .arg(servo.sweeping ? QLatin1String(" hand=sweeping") : QString())
                       + QStringLiteral(" temperature=%1 supply=%2")
                             .arg(servo.temperature)
                             .arg(servo.supplyVolts, 0, 'f', 1)
                       + (servo.powered ? QString() : QStringLiteral(" power=off"))
                       + (servo.blocked ? QStringLiteral(" horn=blocked") : QString())
                       + (servo.overloadLatched ? QStringLiteral(" overload=latched") : QString())
                       + (servo.heatPerSecond != 0.0
                              ? QStringLiteral(" heat=%1").arg(servo.heatPerSecond)
                              : QString()));
    }
    return entries.join(QLatin1String("; "));
}

const QStringList kBenchCaseCommands {
    QStringLiteral("power"),   QStringLiteral("break-chain"), QStringLiteral("supply"),
    QStringLiteral("heat"),    QStringLiteral("temperature"), QStringLiteral("block"),
    QStringLiteral("unblock"), QStringLiteral("latch"),       QStringLiteral("power-cut")};

std::optional<double> numberIn(const QString &text, double low, double high)
{
    bool ok = false;
    const double value = text.toDouble(&ok);
    if (!ok || !std::isfinite(value) || value < low || value > high)
        return std::nullopt;
    return value;
}

// The bench cases: a servo without power, a broken daisy chain, the supply, heat, a blocked horn
// and a latched overload. `words` follow the command.
QString runBenchCase(const QString &command, const QStringList &words, VirtualFeetechBus &bus)
{
    const auto usage = [&](const QString &form) {
        return error(ServosimTr::tr("%1 takes: %2").arg(command, form));
    };
    QString why;
    if (command == QLatin1String("supply")) {
        if (words.size() != 1)
            return usage(QStringLiteral("supply VOLTS"));
        const auto volts = numberIn(words.first(), 0.0, 30.0);
        if (!volts)
            return error(
                ServosimTr::tr("\"%1\" is not a supply from 0 to 30 V").arg(words.first()));
        bus.setSupplyVoltage(*volts);
        return ok(ServosimTr::tr("the supply is %1 V").arg(*volts, 0, 'f', 1));
    }
    if (command == QLatin1String("break-chain") && words.size() == 1
        && words.first() == QLatin1String("none")) {
        bus.setChainBreakAfter(-1);
        return ok(ServosimTr::tr("the daisy chain is whole"));
    }
    static const QHash<QString, QString> kForms {
        {QStringLiteral("power"), QStringLiteral("power SERVO on|off")},
        {QStringLiteral("break-chain"), QStringLiteral("break-chain SERVO|none")},
        {QStringLiteral("heat"), QStringLiteral("heat SERVO C_PER_S")},
        {QStringLiteral("temperature"), QStringLiteral("temperature SERVO C")},
        {QStringLiteral("block"), QStringLiteral("block SERVO [PERMILLE]")},
        {QStringLiteral("unblock"), QStringLiteral("unblock SERVO")},
        {QStringLiteral("latch"), QStringLiteral("latch SERVO")},
        {QStringLiteral("power-cut"), QStringLiteral("power-cut SERVO after-unlock|after-write")}};
    const bool oneWord = command == QLatin1String("break-chain")
        || command == QLatin1String("unblock") || command == QLatin1String("latch");
    const bool optionalSecond = command == QLatin1String("block");
    if (words.isEmpty() || words.size() > 2 || (oneWord && words.size() != 1)
        || (!oneWord && !optionalSecond && words.size() != 2))
        return usage(kForms.value(command));
    const auto index = servoIndex(bus, words.first(), &why);
    if (!index)
        return error(why);
    VirtualFeetechServo &servo = bus.servo(*index);
    const QString who = place(bus, *index);
    const QString second = words.value(1);

    if (command == QLatin1String("power")) {
        if (second != QLatin1String("on") && second != QLatin1String("off"))
            return usage(kForms.value(command));
        bus.setPowered(*index, second == QLatin1String("on"));
        return ok(second == QLatin1String("on") ? ServosimTr::tr("%1 has power").arg(who)
                                                : ServosimTr::tr("%1 has no power").arg(who));
    }
    if (command == QLatin1String("power-cut")) {
        const auto cut = powerCutFromName(second);
        if (!cut)
            return usage(kForms.value(command));
        bus.armPowerCut(*index, *cut);
        return ok(*cut == PowerCut::AfterUnlock
                      ? ServosimTr::tr("%1 loses power once its EEPROM lock is opened").arg(who)
                      : ServosimTr::tr("%1 loses power after its next EEPROM write").arg(who));
    }
    if (command == QLatin1String("break-chain")) {
        bus.setChainBreakAfter(*index);
        return ok(ServosimTr::tr("the daisy chain is broken after %1").arg(who));
    }
    if (command == QLatin1String("heat")) {
        const auto rate = numberIn(second, -10.0, 10.0);
        if (!rate)
            return error(ServosimTr::tr("\"%1\" is not a rate from -10 to 10 °C/s").arg(second));
        servo.setTemperatureRise(*rate);
        return ok(ServosimTr::tr("%1 warms by %2 °C/s").arg(who).arg(*rate));
    }
    if (command == QLatin1String("temperature")) {
        const auto celsius = numberIn(second, -20.0, 120.0);
        if (!celsius)
            return error(
                ServosimTr::tr("\"%1\" is not a temperature from -20 to 120 °C").arg(second));
        servo.setTemperature(*celsius);
        return ok(ServosimTr::tr("%1 is at %2 °C").arg(who).arg(*celsius));
    }
    if (command == QLatin1String("block")) {
        const auto permille =
            second.isEmpty() ? std::optional<double>(1000.0) : numberIn(second, -1000.0, 1000.0);
        if (!permille || *permille != std::round(*permille))
            return error(ServosimTr::tr("\"%1\" is not a load from -1000 to 1000 ‰").arg(second));
        servo.setExternalLoad(int(*permille));
        return ok(ServosimTr::tr("%1's horn is held with a load of %2 ‰").arg(who).arg(*permille));
    }
    if (command == QLatin1String("unblock")) {
        servo.setExternalLoad(0);
        return ok(ServosimTr::tr("%1's horn is free").arg(who));
    }
    // latch
    servo.setOverloadLatched(true);
    return ok(ServosimTr::tr("%1's overload is latched until a power cycle").arg(who));
}

} // namespace

QVector<SimulatedServo> simulatedServos(VirtualFeetechBus &bus)
{
    QVector<SimulatedServo> servos;
    for (int i = 0; i < bus.servoCount(); ++i) {
        const VirtualFeetechServo &servo = bus.servo(i);
        const bool scs = servo.family() == feetech::Family::Scs;
        SimulatedServo entry {i,
                              servo.id(),
                              servo.baudRate(),
                              servo.modelName(),
                              servo.value(u"present_position"),
                              scs ? ServoMotion::kScsMaxPosition
                                  : ServoMotion::kFullCircleSteps - 1,
                              servo.value(u"torque_enable") != 0,
                              bus.hand().isSweeping(i)};
        entry.powered = bus.isPowered(i);
        entry.blocked = servo.externalLoad() != 0;
        entry.overloadLatched = servo.overloadLatched();
        entry.heatPerSecond = servo.temperatureRise();
        entry.temperature = servo.value(u"present_temperature");
        entry.supplyVolts = servo.supplyVoltage();
        servos.append(entry);
    }
    return servos;
}

QString benchCondition(const SimulatedServo &servo)
{
    QStringList words;
    if (!servo.powered)
        words.append(ServosimTr::tr("no power"));
    if (servo.blocked)
        words.append(ServosimTr::tr("horn blocked"));
    if (servo.overloadLatched)
        words.append(ServosimTr::tr("overload latched"));
    if (servo.heatPerSecond > 0)
        words.append(ServosimTr::tr("heating %1 °C/s").arg(servo.heatPerSecond));
    else if (servo.heatPerSecond < 0)
        words.append(ServosimTr::tr("cooling %1 °C/s").arg(-servo.heatPerSecond));
    return words.join(QLatin1String(", "));
}

std::optional<int> servoIndex(const VirtualFeetechBus &bus, const QString &reference,
                              QString *error)
{
    if (reference.startsWith(u'#')) {
        const auto number = util::parseInteger(reference.mid(1));
        if (!number || *number < 1 || *number > bus.servoCount()) {
            if (error)
                *error = ServosimTr::tr("there is no servo %1: the bus has #1 to #%2")
                             .arg(reference)
                             .arg(bus.servoCount());
            return std::nullopt;
        }
        return int(*number - 1);
    }
    const auto id = util::parseInteger(reference);
    if (!id || *id < 0 || *id > feetech::kMaxServoId) {
        if (error)
            *error = ServosimTr::tr("\"%1\" names no servo: give an ID (0 to %2) or a place as #N")
                         .arg(reference)
                         .arg(feetech::kMaxServoId);
        return std::nullopt;
    }
    SimRefusal why;
    const auto index = bus.uniqueIndexOf(quint8(*id), &why);
    if (!index && error)
        *error = why.describe();
    return index;
}

QString simulatorCommandHelp()
{
    return ServosimTr::tr(
        "commands: turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | "
        "release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | "
        "power-cycle | power SERVO on|off | break-chain SERVO|none | supply VOLTS | "
        "heat SERVO C_PER_S | temperature SERVO C | block SERVO [PERMILLE] | "
        "unblock SERVO | latch SERVO | power-cut SERVO after-unlock|after-write | "
        "help; SERVO is an ID or a place #N from list");
}

QString runSimulatorCommand(const QString &line, Simulator &simulator)
{
    static const QRegularExpression kSpaces(QStringLiteral("\\s+"));
    QStringList words = line.trimmed().split(kSpaces, Qt::SkipEmptyParts);
    if (words.isEmpty())
        return {};
    const QString command = words.takeFirst().toLower();
    if (command == QLatin1String("help"))
        return ok(simulatorCommandHelp());
    static const QStringList kCommands {QStringLiteral("turn"),    QStringLiteral("sweep"),
                                        QStringLiteral("release"), QStringLiteral("plug"),
                                        QStringLiteral("unplug"),  QStringLiteral("set-id"),
                                        QStringLiteral("list"),    QStringLiteral("power-cycle")};
    if (!kCommands.contains(command) && !kBenchCaseCommands.contains(command))
        return error(ServosimTr::tr("unknown command \"%1\": try help").arg(command));
    const auto usage = [&](const QString &form) {
        return error(ServosimTr::tr("%1 takes: %2").arg(command, form));
    };

    simulator.advanceNow();
    if (command == QLatin1String("power-cycle")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("power-cycle"));
        simulator.powerCycle();
        return ok(ServosimTr::tr("power-cycled"));
    }
    VirtualFeetechBus *bus = simulator.feetechBus();
    if (!bus)
        return error(ServosimTr::tr("%1 is for a Feetech bus; this is a PTK servo").arg(command));
    QString why;

    if (kBenchCaseCommands.contains(command))
        return runBenchCase(command, words, *bus);
    if (command == QLatin1String("list")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("list"));
        return ok(listLine(simulatedServos(*bus)));
    }
    if (command == QLatin1String("release")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("release"));
        return ok(ServosimTr::tr("the hand let go of %n sweep(s)", nullptr, bus->hand().stop()));
    }
    if (command == QLatin1String("plug")) {
        if (words.size() != 1)
            return usage(QStringLiteral("plug ID:MODEL[@BAUD]"));
        OptionError badSpec;
        const auto spec = parseServoSpec(words.first(), QStringLiteral("plug"), &badSpec);
        if (!spec)
            return error(badSpec.describe());
        SimRefusal refusal;
        if (!bus->plug(*spec, &refusal))
            return error(refusal.describe());
        const int index = bus->servoCount() - 1;
        const VirtualFeetechServo &servo = bus->servo(index);
        return ok(ServosimTr::tr("plugged %1: %2 at %3 bps")
                      .arg(place(*bus, index), servo.modelName())
                      .arg(servo.baudRate()));
    }
    if (command == QLatin1String("turn")) {
        if (words.size() != 2)
            return usage(QStringLiteral("turn SERVO POS"));
        const auto index = servoIndex(*bus, words.at(0), &why);
        if (!index)
            return error(why);
        const auto position = util::parseInteger(words.at(1));
        if (!position || *position < 0 || *position > 4095)
            return error(
                ServosimTr::tr("\"%1\" is not a position from 0 to 4095").arg(words.at(1)));
        SimRefusal refusal;
        if (!bus->hand().turnServo(*index, int(*position), &refusal))
            return error(refusal.describe());
        return ok(ServosimTr::tr("turned %1 to %2").arg(place(*bus, *index)).arg(*position));
    }
    if (command == QLatin1String("sweep")) {
        if (words.size() < 4)
            return usage(QStringLiteral("sweep SERVO FROM TO SECONDS [CYCLES] [up|down]"));
        const auto index = servoIndex(*bus, words.at(0), &why);
        if (!index)
            return error(why);
        // The ID field is checked by servoIndex; the sweep's own fields by parseHandSweep.
        QStringList fields = words;
        fields[0] = QString::number(bus->servo(*index).id());
        OptionError badSweep;
        const auto sweep = parseHandSweep(fields, QStringLiteral("sweep"), &badSweep);
        if (!sweep)
            return error(badSweep.describe());
        SimRefusal refusal;
        if (!bus->hand().sweepServo(*index, sweep->from, sweep->to, sweep->seconds, sweep->cycles,
                                    sweep->way, &refusal))
            return error(refusal.describe());
        const QString times = sweep->cycles == 0
            ? ServosimTr::tr("until released")
            : ServosimTr::tr("%n time(s)", nullptr, sweep->cycles);
        return ok(ServosimTr::tr("sweeping %1 from %2 to %3 and back every %4 s, %5")
                      .arg(place(*bus, *index))
                      .arg(sweep->from)
                      .arg(sweep->to)
                      .arg(sweep->seconds)
                      .arg(times));
    }
    if (command == QLatin1String("unplug")) {
        if (words.size() != 1)
            return usage(QStringLiteral("unplug SERVO"));
        const auto index = servoIndex(*bus, words.first(), &why);
        if (!index)
            return error(why);
        const QString gone = place(*bus, *index);
        bus->unplug(*index);
        return ok(ServosimTr::tr("unplugged %1").arg(gone));
    }
    // set-id
    if (words.size() != 2)
        return usage(QStringLiteral("set-id SERVO ID"));
    const auto index = servoIndex(*bus, words.at(0), &why);
    if (!index)
        return error(why);
    const auto id = util::parseInteger(words.at(1));
    if (!id || *id < 0 || *id > feetech::kMaxServoId)
        return error(ServosimTr::tr("\"%1\" is not an ID from 0 to %2")
                         .arg(words.at(1))
                         .arg(feetech::kMaxServoId));
    SimRefusal refusal;
    if (!bus->setServoId(*index, int(*id), &refusal))
        return error(refusal.describe());
    return ok(ServosimTr::tr("servo #%1 is now at ID %2").arg(*index + 1).arg(*id));
}

} // namespace sim
