// servosim's standard-input commands: turn, sweep, release, plug, unplug, set-id, list,
// power-cycle and help, each answered with one line.
#include "sim/simcommands.h"

#include "sim/simulator.h"
#include "util/hex.h"

#include <QCoreApplication>
#include <QRegularExpression>

namespace sim {

namespace {

struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servosim)
};

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
    return Tr::tr("#%1 (ID %2)").arg(index + 1).arg(bus.servo(index).id());
}

QString listLine(const QVector<SimulatedServo> &servos)
{
    if (servos.isEmpty())
        return Tr::tr("no servos");
    QStringList entries;
    for (const SimulatedServo &servo : servos) {
        entries.append(QStringLiteral("#%1 id=%2 baud=%3 model=%4 position=%5 torque=%6%7")
                           .arg(servo.index + 1)
                           .arg(servo.id)
                           .arg(servo.baud)
                           .arg(servo.model)
                           .arg(servo.position)
                           .arg(servo.torqueOn ? QLatin1String("on") : QLatin1String("off"))
                           .arg(servo.sweeping ? QLatin1String(" hand=sweeping") : QString()));
    }
    return entries.join(QLatin1String("; "));
}

} // namespace

QVector<SimulatedServo> simulatedServos(VirtualFeetechBus &bus)
{
    QVector<SimulatedServo> servos;
    for (int i = 0; i < bus.servoCount(); ++i) {
        const VirtualFeetechServo &servo = bus.servo(i);
        const bool scs = servo.family() == feetech::Family::Scs;
        servos.append({i, servo.id(), servo.baudRate(), servo.modelName(),
                       servo.value(u"present_position"),
                       scs ? ServoMotion::kScsMaxPosition : ServoMotion::kFullCircleSteps - 1,
                       servo.value(u"torque_enable") != 0, bus.hand().isSweeping(i)});
    }
    return servos;
}

std::optional<int> servoIndex(const VirtualFeetechBus &bus, const QString &reference,
                              QString *error)
{
    if (reference.startsWith(u'#')) {
        const auto number = util::parseInteger(reference.mid(1));
        if (!number || *number < 1 || *number > bus.servoCount()) {
            if (error)
                *error = Tr::tr("there is no servo %1: the bus has #1 to #%2")
                             .arg(reference)
                             .arg(bus.servoCount());
            return std::nullopt;
        }
        return int(*number - 1);
    }
    const auto id = util::parseInteger(reference);
    if (!id || *id < 0 || *id > feetech::kMaxServoId) {
        if (error)
            *error = Tr::tr("\"%1\" names no servo: give an ID (0 to %2) or a place as #N")
                         .arg(reference)
                         .arg(feetech::kMaxServoId);
        return std::nullopt;
    }
    return bus.uniqueIndexOf(quint8(*id), error);
}

QString simulatorCommandHelp()
{
    return Tr::tr("commands: turn SERVO POS | sweep SERVO FROM TO SECONDS [CYCLES] [up|down] | "
                  "release | plug ID:MODEL[@BAUD] | unplug SERVO | set-id SERVO ID | list | "
                  "power-cycle | help; SERVO is an ID or a place #N from list");
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
    if (!kCommands.contains(command))
        return error(Tr::tr("unknown command \"%1\": try help").arg(command));
    const auto usage = [&](const QString &form) {
        return error(Tr::tr("%1 takes: %2").arg(command, form));
    };

    simulator.advanceNow();
    if (command == QLatin1String("power-cycle")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("power-cycle"));
        simulator.powerCycle();
        return ok(Tr::tr("power-cycled"));
    }
    VirtualFeetechBus *bus = simulator.feetechBus();
    if (!bus)
        return error(Tr::tr("%1 is for a Feetech bus; this is a PTK servo").arg(command));
    QString why;

    if (command == QLatin1String("list")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("list"));
        return ok(listLine(simulatedServos(*bus)));
    }
    if (command == QLatin1String("release")) {
        if (!words.isEmpty())
            return usage(QStringLiteral("release"));
        return ok(Tr::tr("the hand let go of %n sweep(s)", nullptr, bus->hand().stop()));
    }
    if (command == QLatin1String("plug")) {
        if (words.size() != 1)
            return usage(QStringLiteral("plug ID:MODEL[@BAUD]"));
        const auto spec = parseServoSpec(words.first(), QStringLiteral("plug"), &why);
        if (!spec || !bus->plug(*spec, &why))
            return error(why);
        const int index = bus->servoCount() - 1;
        const VirtualFeetechServo &servo = bus->servo(index);
        return ok(Tr::tr("plugged %1: %2 at %3 bps")
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
            return error(Tr::tr("\"%1\" is not a position from 0 to 4095").arg(words.at(1)));
        if (!bus->hand().turnServo(*index, int(*position), &why))
            return error(why);
        return ok(Tr::tr("turned %1 to %2").arg(place(*bus, *index)).arg(*position));
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
        const auto sweep = parseHandSweep(fields, QStringLiteral("sweep"), &why);
        if (!sweep)
            return error(why);
        if (!bus->hand().sweepServo(*index, sweep->from, sweep->to, sweep->seconds, sweep->cycles,
                                    sweep->way, &why))
            return error(why);
        const QString times = sweep->cycles == 0 ? Tr::tr("until released")
                                                 : Tr::tr("%n time(s)", nullptr, sweep->cycles);
        return ok(Tr::tr("sweeping %1 from %2 to %3 and back every %4 s, %5")
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
        return ok(Tr::tr("unplugged %1").arg(gone));
    }
    // set-id
    if (words.size() != 2)
        return usage(QStringLiteral("set-id SERVO ID"));
    const auto index = servoIndex(*bus, words.at(0), &why);
    if (!index)
        return error(why);
    const auto id = util::parseInteger(words.at(1));
    if (!id || *id < 0 || *id > feetech::kMaxServoId)
        return error(
            Tr::tr("\"%1\" is not an ID from 0 to %2").arg(words.at(1)).arg(feetech::kMaxServoId));
    if (!bus->setServoId(*index, int(*id), &why))
        return error(why);
    return ok(Tr::tr("servo #%1 is now at ID %2").arg(*index + 1).arg(*id));
}

} // namespace sim
