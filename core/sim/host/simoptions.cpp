// servosim's command line: servosim ptk|feetech --link PATH [options].
#include "simoptions.h"

#include "hex.h"
#include "servosimtr.h"

#include <QCoreApplication>

namespace sim {

QString simulatorUsage()
{
    return ServosimTr::tr(
        "usage: servosim ptk --link PATH [--values KEY=V,...] [options]\n"
        "       servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] "
        "[--state FILE] [options]\n"
        "       servosim feetech --link PATH --robot so101 [--servo ...] [options]\n"
        "\n"
        "Feetech options:\n"
        "  --servo ID:MODEL[@BAUD]  a servo on the bus (BAUD: the family's default rate)\n"
        "  --allow-shared-ids       let two --servo share an ID at one rate (replies collide)\n"
        "  --robot NAME             a set-up arm from a built-in template, horns at rest:\n"
        "                           so101, so100 (follower arms), so101-leader, so100-leader\n"
        "  --hand ID:FROM:TO:SECONDS[:CYCLES][:up|down]\n"
        "                           the hand sweeps a joint whose torque is off from FROM to\n"
        "                           TO and back in SECONDS, CYCLES times (0 or none: until\n"
        "                           released); up or down crosses the 4095/0 seam if needed\n"
        "  --state FILE             keep the servos' EEPROM in FILE across runs\n"
        "  --command LINE           a standard-input command run before \"ready\", e.g.\n"
        "                           \"break-chain 2\", \"supply 12.6\", \"block 3\" (repeatable)\n"
        "\n"
        "options:\n"
        "  --echo                 send every host byte back first (single-wire adapter)\n"
        "  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS,lost=P (P: 0-1;\n"
        "                         lost: a host frame never reaches the servos)\n"
        "  --seed N               seed of the fault generator (default 1)\n"
        "  --log FILE             log every frame in and out, hex, timestamped\n"
        "  --reply-delay-us N     extra delay before every reply\n"
        "  --adapter PROFILE      deliver replies as a USB adapter does: ideal (the pty's own\n"
        "                         timing, the default), instant (the moment a frame is\n"
        "                         complete, in no wire time), ftdi (16 ms latency timer),\n"
        "                         ftdi-1ms, ch340, ch343, cp2102\n"
        "\n"
        "Prints \"ready PATH\" once a client can open PATH; runs until SIGINT or SIGTERM;\n"
        "SIGHUP power-cycles the servos. Reads commands on standard input, one a line, and\n"
        "answers each with one line, \"ok ...\" or \"error ...\" (\"help\" lists them); the\n"
        "end of standard input does not stop it.\n");
}

std::optional<SimulatorOptions> parseSimulatorArguments(const QStringList &arguments,
                                                        QString *error)
{
    const auto fail = [&](const QString &what) -> std::optional<SimulatorOptions> {
        if (error)
            *error = what;
        return std::nullopt;
    };
    if (arguments.isEmpty())
        return fail(ServosimTr::tr("name a protocol: ptk or feetech"));
    SimulatorOptions options;
    if (arguments.first() == QLatin1String("ptk"))
        options.kind = SimulatorOptions::Kind::Ptk;
    else if (arguments.first() == QLatin1String("feetech"))
        options.kind = SimulatorOptions::Kind::Feetech;
    else
        return fail(
            ServosimTr::tr("unknown protocol \"%1\": use ptk or feetech").arg(arguments.first()));
    const bool feetech = options.kind == SimulatorOptions::Kind::Feetech;

    for (int i = 1; i < arguments.size(); ++i) {
        const QString option = arguments.at(i);
        const auto value = [&]() -> std::optional<QString> {
            if (i + 1 >= arguments.size())
                return std::nullopt;
            return arguments.at(++i);
        };
        if (option == QLatin1String("--echo")) {
            options.echo = true;
            continue;
        }
        if (option == QLatin1String("--allow-shared-ids")) {
            if (!feetech)
                return fail(ServosimTr::tr("--allow-shared-ids is for a Feetech bus"));
            options.allowSharedIds = true;
            continue;
        }
        static const QStringList kWithValue {
            QStringLiteral("--link"),           QStringLiteral("--faults"),
            QStringLiteral("--seed"),           QStringLiteral("--log"),
            QStringLiteral("--reply-delay-us"), QStringLiteral("--values"),
            QStringLiteral("--servo"),          QStringLiteral("--state"),
            QStringLiteral("--robot"),          QStringLiteral("--hand"),
            QStringLiteral("--command"),        QStringLiteral("--adapter")};
        if (!kWithValue.contains(option))
            return fail(ServosimTr::tr("unknown option \"%1\"").arg(option));
        const auto text = value();
        if (!text)
            return fail(ServosimTr::tr("%1 needs a value").arg(option));
        if (option == QLatin1String("--link")) {
            options.linkPath = *text;
        } else if (option == QLatin1String("--faults")) {
            OptionError why;
            const auto faults = FaultSettings::parse(*text, &why);
            if (!faults)
                return fail(why.describe());
            options.faults = *faults;
        } else if (option == QLatin1String("--seed")) {
            const auto seed = util::parseInteger(*text);
            if (!seed || *seed < 0 || *seed > 0xFFFFFFFFLL)
                return fail(ServosimTr::tr("--seed must be a whole number from 0 to 4294967295"));
            options.seed = quint32(*seed);
        } else if (option == QLatin1String("--log")) {
            options.logPath = *text;
        } else if (option == QLatin1String("--reply-delay-us")) {
            const auto delay = util::parseInteger(*text);
            if (!delay || *delay < 0 || *delay > 10'000'000)
                return fail(ServosimTr::tr("--reply-delay-us must be 0 to 10000000"));
            options.replyDelayUs = *delay;
        } else if (option == QLatin1String("--adapter")) {
            options.adapter.reset();
            options.instant = *text == QLatin1String("instant");
            if (const auto profile = adapterProfile(*text)) {
                options.adapter = profile;
            } else if (*text != QLatin1String("ideal") && !options.instant) {
                const QStringList names = adapterProfileNames() << QStringLiteral("instant");
                return fail(ServosimTr::tr("unknown adapter \"%1\": use %2")
                                .arg(*text, names.join(QStringLiteral(", "))));
            }
        } else if (option == QLatin1String("--values")) {
            if (feetech)
                return fail(ServosimTr::tr("--values is for the PTK servo"));
            options.ptkValues = *text;
        } else if (option == QLatin1String("--state")) {
            if (!feetech)
                return fail(ServosimTr::tr("--state is for a Feetech bus"));
            options.statePath = *text;
        } else if (option == QLatin1String("--robot")) {
            if (!feetech)
                return fail(ServosimTr::tr("--robot is for a Feetech bus"));
            if (options.robot)
                return fail(ServosimTr::tr("--robot may be given once"));
            OptionError why;
            options.robot = simulatedRobot(*text, &why);
            if (!options.robot)
                return fail(why.describe());
        } else if (option == QLatin1String("--hand")) {
            if (!feetech)
                return fail(ServosimTr::tr("--hand is for a Feetech bus"));
            OptionError why;
            const auto sweep =
                parseHandSweep(text->split(u':'), QStringLiteral("--hand \"%1\"").arg(*text), &why);
            if (!sweep)
                return fail(why.describe());
            options.sweeps.append(*sweep);
        } else if (option == QLatin1String("--command")) {
            options.commands.append(*text);
        } else if (option == QLatin1String("--servo")) {
            if (!feetech)
                return fail(ServosimTr::tr("--servo is for a Feetech bus"));
            OptionError why;
            const auto spec = parseServoSpec(*text, QStringLiteral("--servo"), &why);
            if (!spec)
                return fail(why.describe());
            options.servos.append(*spec);
        }
    }
    if (options.linkPath.isEmpty())
        return fail(ServosimTr::tr("--link PATH is required"));
    if (options.robot) {
        // The arm's joints come first, at the template's rate, whatever order the options had.
        options.servos = robotServos(*options.robot) + options.servos;
    }
    if (feetech && options.servos.isEmpty())
        return fail(ServosimTr::tr(
            "a Feetech bus needs at least one --servo ID:MODEL[@BAUD] or a --robot"));
    return options;
}

std::optional<FeetechServoSpec> parseServoSpec(const QString &text, const QString &source,
                                               OptionError *error)
{
    using Code = OptionError::Code;
    const auto fail = [&](Code code, qint64 value = 0) -> std::optional<FeetechServoSpec> {
        refused(OptionError(code, text, source, value), error);
        return std::nullopt;
    };
    const int colon = text.indexOf(u':');
    const int at = text.indexOf(u'@');
    const auto id = util::parseInteger(text.left(colon));
    if (colon <= 0 || !id)
        return fail(Code::NotAServoSpec);
    if (*id < 0 || *id > feetech::kMaxServoId)
        return fail(Code::ServoIdOverMax, *id);
    FeetechServoSpec spec;
    spec.id = quint8(*id);
    spec.model = text.mid(colon + 1, at > colon ? at - colon - 1 : -1);
    if (spec.model.isEmpty())
        return fail(Code::ServoWithoutModel);
    if (at > colon) {
        const auto baud = util::parseInteger(text.mid(at + 1));
        if (!baud || *baud <= 0 || *baud > 10'000'000)
            return fail(Code::ServoBadBaud);
        spec.baud = qint32(*baud);
    }
    return spec;
}

std::optional<HandSweep> parseHandSweep(const QStringList &fields, const QString &source,
                                        OptionError *error)
{
    using Code = OptionError::Code;
    const auto fail = [&](Code code, const QString &text = {}) -> std::optional<HandSweep> {
        refused(OptionError(code, text, source), error);
        return std::nullopt;
    };
    QStringList values = fields;
    HandSweep sweep;
    if (!values.isEmpty()
        && (values.last() == QLatin1String("up") || values.last() == QLatin1String("down"))) {
        sweep.way = values.last() == QLatin1String("up") ? Hand::Way::Up : Hand::Way::Down;
        values.removeLast();
    }
    if (values.size() < 4 || values.size() > 5)
        return fail(Code::SweepFields);
    const auto id = util::parseInteger(values.at(0));
    if (!id || *id < 0 || *id > feetech::kMaxServoId)
        return fail(Code::SweepBadId, values.at(0));
    sweep.id = quint8(*id);
    const auto from = util::parseInteger(values.at(1));
    const auto to = util::parseInteger(values.at(2));
    if (!from || !to || *from < 0 || *to < 0 || *from > 4095 || *to > 4095)
        return fail(Code::SweepBadPositions);
    sweep.from = int(*from);
    sweep.to = int(*to);
    bool ok = false;
    sweep.seconds = values.at(3).toDouble(&ok);
    if (!ok || !(sweep.seconds > 0.0) || sweep.seconds > Hand::kMaxSweepSeconds)
        return fail(Code::SweepBadSeconds, values.at(3));
    if (values.size() == 5) {
        const auto cycles = util::parseInteger(values.at(4));
        if (!cycles || *cycles < 0 || *cycles > Hand::kMaxSweepCycles)
            return fail(Code::SweepBadCycles, values.at(4));
        sweep.cycles = int(*cycles);
    }
    return sweep;
}

std::optional<feetech::RobotTemplate> simulatedRobot(const QString &name, OptionError *error)
{
    const QString key = name.trimmed().toLower();
    if (!OptionError::simulatedRobotNames().contains(key)) {
        refused(OptionError(OptionError::Code::UnknownRobot, name), error);
        return std::nullopt;
    }
    const QString file = key.contains(u'-') ? key : key + QLatin1String("-follower");
    util::FileError why;
    auto robot = feetech::loadRobotTemplate(QStringLiteral(":/robots/%1.json").arg(file), &why);
    if (!robot)
        refused(OptionError(OptionError::Code::BadRobotTemplate, why.describe()), error);
    return robot;
}

QVector<FeetechServoSpec> robotServos(const feetech::RobotTemplate &robot)
{
    QVector<FeetechServoSpec> servos;
    for (const feetech::RobotJoint &joint : robot.joints)
        servos.append({quint8(joint.id), joint.model, robot.baud});
    return servos;
}

} // namespace sim
