// servosim's command line: servosim ptk|feetech --link PATH [options].
#include "sim/simulator.h"

#include "util/hex.h"

#include <QCoreApplication>

namespace sim {

namespace {
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(servosim)
};
} // namespace

QString simulatorUsage()
{
    return Tr::tr(
        "usage: servosim ptk --link PATH [--values KEY=V,...] [options]\n"
        "       servosim feetech --link PATH --servo ID:MODEL[@BAUD] [--servo ...] "
        "[--state FILE] [options]\n"
        "\n"
        "options:\n"
        "  --echo                 send every host byte back first (single-wire adapter)\n"
        "  --faults SPEC          drop=P,corrupt=P,truncate=P,noise=P,delay=MS\n"
        "  --seed N               seed of the fault generator (default 1)\n"
        "  --log FILE             log every frame in and out, hex, timestamped\n"
        "  --reply-delay-us N     extra delay before every reply\n"
        "\n"
        "Prints \"ready PATH\" once a client can open PATH; runs until SIGINT or SIGTERM;\n"
        "SIGHUP power-cycles the servos.\n");
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
        return fail(Tr::tr("name a protocol: ptk or feetech"));
    SimulatorOptions options;
    if (arguments.first() == QLatin1String("ptk"))
        options.kind = SimulatorOptions::Kind::Ptk;
    else if (arguments.first() == QLatin1String("feetech"))
        options.kind = SimulatorOptions::Kind::Feetech;
    else
        return fail(Tr::tr("unknown protocol \"%1\": use ptk or feetech").arg(arguments.first()));
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
        static const QStringList kWithValue {
            QStringLiteral("--link"),           QStringLiteral("--faults"),
            QStringLiteral("--seed"),           QStringLiteral("--log"),
            QStringLiteral("--reply-delay-us"), QStringLiteral("--values"),
            QStringLiteral("--servo"),          QStringLiteral("--state")};
        if (!kWithValue.contains(option))
            return fail(Tr::tr("unknown option \"%1\"").arg(option));
        const auto text = value();
        if (!text)
            return fail(Tr::tr("%1 needs a value").arg(option));
        if (option == QLatin1String("--link")) {
            options.linkPath = *text;
        } else if (option == QLatin1String("--faults")) {
            const auto faults = FaultSettings::parse(*text, error);
            if (!faults)
                return std::nullopt;
            options.faults = *faults;
        } else if (option == QLatin1String("--seed")) {
            const auto seed = util::parseInteger(*text);
            if (!seed || *seed < 0 || *seed > 0xFFFFFFFFLL)
                return fail(Tr::tr("--seed must be a whole number from 0 to 4294967295"));
            options.seed = quint32(*seed);
        } else if (option == QLatin1String("--log")) {
            options.logPath = *text;
        } else if (option == QLatin1String("--reply-delay-us")) {
            const auto delay = util::parseInteger(*text);
            if (!delay || *delay < 0 || *delay > 10'000'000)
                return fail(Tr::tr("--reply-delay-us must be 0 to 10000000"));
            options.replyDelayUs = *delay;
        } else if (option == QLatin1String("--values")) {
            if (feetech)
                return fail(Tr::tr("--values is for the PTK servo"));
            options.ptkValues = *text;
        } else if (option == QLatin1String("--state")) {
            if (!feetech)
                return fail(Tr::tr("--state is for a Feetech bus"));
            options.statePath = *text;
        } else if (option == QLatin1String("--servo")) {
            if (!feetech)
                return fail(Tr::tr("--servo is for a Feetech bus"));
            // ID:MODEL[@BAUD]
            const int colon = text->indexOf(u':');
            const int at = text->indexOf(u'@');
            const auto id = util::parseInteger(text->left(colon));
            if (colon <= 0 || !id)
                return fail(Tr::tr("--servo \"%1\" is not ID:MODEL[@BAUD]").arg(*text));
            if (*id < 0 || *id > 253)
                return fail(Tr::tr("--servo \"%1\": ID %2 is over 253").arg(*text).arg(*id));
            FeetechServoSpec spec;
            spec.id = quint8(*id);
            spec.model = text->mid(colon + 1, at > colon ? at - colon - 1 : -1);
            if (spec.model.isEmpty())
                return fail(Tr::tr("--servo \"%1\" names no model").arg(*text));
            if (at > colon) {
                const auto baud = util::parseInteger(text->mid(at + 1));
                if (!baud || *baud <= 0 || *baud > 10'000'000)
                    return fail(Tr::tr("--servo \"%1\": bad baud rate").arg(*text));
                spec.baud = qint32(*baud);
            }
            options.servos.append(spec);
        }
    }
    if (options.linkPath.isEmpty())
        return fail(Tr::tr("--link PATH is required"));
    if (feetech && options.servos.isEmpty())
        return fail(Tr::tr("a Feetech bus needs at least one --servo ID:MODEL[@BAUD]"));
    return options;
}

} // namespace sim
