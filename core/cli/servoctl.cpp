// servoctl commands: ports, decode, packet (frame builder) and their argument handling.
#include "servoctl.h"

#include "arguments.h"
#include "decoder.h"
#include "detectcommands.h"
#include "feetechcommands.h"
#include "feetechdescription.h"
#include "feetechpacket.h"
#include "hex.h"
#include "observedservos.h"
#include "ptkcommands.h"
#include "ptkparameters.h"
#include "servoctltr.h"
#include "sharecommand.h"
#include "sharerecording.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QMap>
#include <QSerialPortInfo>
#include <QSet>

#include <functional>

namespace cli {

namespace {

const char *const kUsage = QT_TRANSLATE_NOOP(
    "servoctl",
    "usage: servoctl [--port PATH] [--baud N] [--json] [--trace] <command> [args]\n"
    "\n"
    "commands:\n"
    "  ports                                  list serial ports\n"
    "  detect                                 find out what answers on the port: a PTK servo\n"
    "                                         or a Feetech bus (its rates and servos); only\n"
    "                                         queries, PINGs and READs are sent\n"
    "  doctor [--expect LIST [--baud N]]      say what is wrong with the bus and what to do;\n"
    "                                         LIST: the servos expected, in chain order\n"
    "                                         (1,2,3 or 1-6), at --baud (1000000)\n"
    "  ptk read                               read the PTK servo's thirteen parameters\n"
    "  ptk write NAME=VALUE...                change parameters (full sequence, verified)\n"
    "  ptk save FILE | ptk load FILE          save the servo to a profile / program one\n"
    "  ptk monitor [--duration S] [--csv]     poll continuously, one row per full refresh\n"
    "  feetech scan [--baud N|all] [--ids A-B] [--thorough]\n"
    "                                         find the servos on the bus (IDs 0-253)\n"
    "  feetech ping --id N                    check that a servo answers; its model\n"
    "  feetech read --id N                    read every register of a servo\n"
    "  feetech get --id N KEY...              read some registers\n"
    "  feetech set --id N KEY=VALUE...        write registers (register units), verified\n"
    "  feetech save --id N FILE               save the servo's EEPROM settings to a profile\n"
    "  feetech load --id N FILE               write the values of a profile that differ\n"
    "  feetech load --ids LIST FILE           the same for several servos (1,2,3 or 1-6);\n"
    "                                         FILE may be a robot template: each servo gets\n"
    "                                         its joint's settings by ID; a profile's\n"
    "                                         position_offset is not copied; a servo with\n"
    "                                         torque on is refused offset/limit changes\n"
    "  feetech set-id --id N NEW              give the servo a new ID (refused if taken)\n"
    "  feetech set-baud --id N BAUD           move the servo to another baud rate (bps)\n"
    "  feetech calibrate-middle --id N        make the present position the middle\n"
    "  feetech factory-reset --id N [--backup FILE]\n"
    "                                         save a backup profile, then restore factory values\n"
    "  feetech reboot --id N                  restart the servo and wait for it\n"
    "  feetech lock --id N                    close an EEPROM lock left open, read it back\n"
    "  feetech recover --id N [--check]       after an overload trip: torque off and on, goal\n"
    "                                         at the present position, the overload bit read;\n"
    "                                         still set: the power-cycle steps (exit 1); after\n"
    "                                         the power cycle --check only reads the bit\n"
    "  feetech setup-motor --id N [--baud BPS] [--model MODEL] [--settings ROBOT]\n"
    "                                         the one servo on the bus (any ID, any rate) gets\n"
    "                                         ID N and rate BPS (default 1000000, or the\n"
    "                                         robot's), verified; ROBOT: a robot template file,\n"
    "                                         whose joint with ID N gives the model to expect\n"
    "                                         and the settings to write and verify\n"
    "  feetech identify --id N                wiggle the servo slowly so you see which it is\n"
    "  feetech health --ids LIST [--move-test]\n"
    "                                         check each servo: model and firmware, voltage and\n"
    "                                         temperature against its limits, status bits, load,\n"
    "                                         20 reads' retries and errors, position against its\n"
    "                                         limits; --move-test also moves each servo without\n"
    "                                         a fault 100 steps and back (rise time, overshoot,\n"
    "                                         steady-state error); exit 1 when a servo has a "
    "fault\n"
    "  feetech check --ids LIST [--robot ROBOT] [--fix]\n"
    "                                         find settings that stop a servo moving or make it\n"
    "                                         misbehave: phase bit 4 (multi-turn), torque limit\n"
    "                                         or maximum torque 0, a mode other than position,\n"
    "                                         angle limits, return delay, an open EEPROM, mixed\n"
    "                                         firmware, voltage limits the supply breaks; ROBOT\n"
    "                                         (so101-follower, ... or a template file) adds its\n"
    "                                         settings; --fix writes the expected values, read\n"
    "                                         back (limits, offset, mode, torque limit and phase\n"
    "                                         only with torque off); exit 1 when something is "
    "left\n"
    "  feetech monitor --ids LIST [--rate HZ|max] [--duration S] [--csv]\n"
    "                                         stream position, speed, load, voltage,\n"
    "                                         temperature and current (SYNC READ)\n"
    "  feetech calibrate --ids LIST [--names LIST] [--full-turn LIST] [--duration S]\n"
    "                    [--dry-run] --out FILE | --update FILE\n"
    "                                         torque off, record each joint's range by hand\n"
    "                                         (Enter ends), centre it on the encoder: offset\n"
    "                                         and limits written, LeRobot calibration saved\n"
    "                                         (--update: into FILE, its other joints kept)\n"
    "  feetech calibration save --ids LIST [--names LIST] FILE\n"
    "                                         the servos' offsets and limits to a LeRobot file\n"
    "  feetech calibration load FILE          write a LeRobot calibration file, verified\n"
    "  feetech record --ids LIST --out FILE [--names LIST] [--rate HZ] [--duration S]\n"
    "                                         record the positions moved by hand (torque left\n"
    "                                         as it is) until --duration or Ctrl-C: CSV with\n"
    "                                         time_s and a column per joint (id_N or NAME@N),\n"
    "                                         in steps; --rate frames per second (default 50)\n"
    "  feetech replay FILE [--speed X] [--ease S] [--loop N] [--release]\n"
    "                                         play a recording: refused when a frame is beyond\n"
    "                                         a servo's angle limits; torque on where the arm\n"
    "                                         stands, a gentle move to the first frame (over S\n"
    "                                         seconds; default from the distance), the frames\n"
    "                                         at their times (--speed 2: twice as fast), N\n"
    "                                         times, then hold (--release: torque off). Ctrl-C\n"
    "                                         holds the arm where it is\n"
    "  feetech teleop --leader PORT --calibration FILE --leader-calibration FILE\n"
    "                 [--rate HZ] [--duration S] [--max-speed DEG_PER_S] [--record FILE]\n"
    "                 [--release] [--norm-mode degrees|range_m100_100]\n"
    "                                         the leader arm on PORT drives this follower,\n"
    "                                         joints matched by name; Ctrl-C holds;\n"
    "                                         --record: the follower's goals, for replay;\n"
    "                                         --norm-mode: as LeRobot maps joints (degrees,\n"
    "                                         its use_degrees: the default)\n"
    "  share --link PATH [--record FILE] [--watch] [--duration S]\n"
    "                                         stand between another program and the servos:\n"
    "                                         it opens PATH, every byte is forwarded; --json\n"
    "                                         prints each transaction, --watch reads the\n"
    "                                         servos in its idle gaps; alerts on stderr\n"
    "  decode [--family ptk|feetech] HEX...   split bytes into frames and explain each\n"
    "  decode --family feetech --log FILE     explain a recording of share, frame by frame\n"
    "  packet ptk query CMD                   print a PTK query frame (CMD: 0x38, 56 or N1..N8)\n"
    "  packet ptk write NAME=VALUE...         print the PTK write frames carrying these values\n"
    "  packet feetech INSTRUCTION [--id N] [--addr A] [--data HEX] [--len N] [--ids LIST]\n"
    "      INSTRUCTION: ping read write reg-write action sync-write sync-read\n"
    "                   recovery reboot reset calibrate\n"
    "\n"
    "options: --port PATH (device commands), --baud N (PTK: 115200; Feetech: the servo's\n"
    "         rate, 1000000),\n"
    "         --echo auto|on|off (single-wire adapter echo; default auto)\n"
    "\n"
    "The overload and thermal guard watches every servo a command drives (identify, and set\n"
    "while it runs); its warnings and actions are printed on stderr.\n"
    "\n"
    "exit status: 0 done, 1 device or link failure, 2 usage error (nothing sent)\n");

class Servoctl
{
public:
    Servoctl(QTextStream &out, QTextStream &err)
        : m_out(out)
        , m_err(err)
    { }

    int run(const QStringList &raw)
    {
        try {
            const Arguments args(
                raw,
                {QStringLiteral("port"),
                 QStringLiteral("baud"),
                 QStringLiteral("family"),
                 QStringLiteral("id"),
                 QStringLiteral("addr"),
                 QStringLiteral("data"),
                 QStringLiteral("len"),
                 QStringLiteral("ids"),
                 QStringLiteral("echo"),
                 QStringLiteral("duration"),
                 QStringLiteral("backup"),
                 QStringLiteral("rate"),
                 QStringLiteral("model"),
                 QStringLiteral("settings"),
                 QStringLiteral("names"),
                 QStringLiteral("full-turn"),
                 QStringLiteral("out"),
                 QStringLiteral("expect"),
                 QStringLiteral("robot"),
                 QStringLiteral("link"),
                 QStringLiteral("record"),
                 QStringLiteral("log"),
                 QStringLiteral("leader"),
                 QStringLiteral("calibration"),
                 QStringLiteral("leader-calibration"),
                 QStringLiteral("max-speed"),
                 QStringLiteral("norm-mode"),
                 QStringLiteral("update"),
                 QStringLiteral("speed"),
                 QStringLiteral("ease"),
                 QStringLiteral("loop")},
                {QStringLiteral("json"), QStringLiteral("trace"), QStringLiteral("csv"),
                 QStringLiteral("thorough"), QStringLiteral("help"), QStringLiteral("version"),
                 QStringLiteral("dry-run"), QStringLiteral("move-test"), QStringLiteral("check"),
                 QStringLiteral("fix"), QStringLiteral("watch"), QStringLiteral("release")});
            m_json = args.flag(QStringLiteral("json"));
            if (args.flag(QStringLiteral("help"))) {
                m_out << ServoctlTr::tr(kUsage);
                return ExitOk;
            }
            if (args.flag(QStringLiteral("version"))) {
                m_out << "servoctl " << QCoreApplication::applicationVersion() << '\n';
                return ExitOk;
            }
            if (args.positional().isEmpty())
                throw UsageError {ServoctlTr::tr("no command given (try servoctl --help)")};
            const QString command = args.positional().first();
            const QStringList rest = args.positional().mid(1);
            if (command == QLatin1String("ports"))
                return ports(args, rest);
            if (command == QLatin1String("decode"))
                return decode(args, rest);
            if (command == QLatin1String("packet"))
                return packet(args, rest);
            if (command == QLatin1String("detect"))
                return runDetectCommand(args, rest, {m_out, m_err, m_json});
            if (command == QLatin1String("doctor"))
                return runDoctorCommand(args, rest, {m_out, m_err, m_json});
            if (command == QLatin1String("ptk"))
                return runPtkCommand(args, rest, {m_out, m_err, m_json});
            if (command == QLatin1String("feetech"))
                return runFeetechCommand(args, rest, {m_out, m_err, m_json});
            if (command == QLatin1String("share"))
                return runShareCommand(args, rest, {m_out, m_err, m_json});
            throw UsageError {
                ServoctlTr::tr("unknown command \"%1\" (try servoctl --help)").arg(command)};
        } catch (const UsageError &error) {
            m_err << "servoctl: " << error.message << '\n';
            m_err.flush();
            return ExitUsage;
        }
    }

private:
    // Options a command accepts besides the global ones.
    static void allowOnly(const Arguments &args, const QStringList &allowed, const QString &what)
    {
        static const QStringList kGlobal {QStringLiteral("port"), QStringLiteral("baud"),
                                          QStringLiteral("echo")};
        for (const QString &name : args.valueNames()) {
            if (!allowed.contains(name) && !kGlobal.contains(name))
                throw UsageError {ServoctlTr::tr("%1 takes no --%2").arg(what, name)};
        }
    }

    void printJson(const QJsonValue &value)
    {
        const QJsonDocument document =
            value.isArray() ? QJsonDocument(value.toArray()) : QJsonDocument(value.toObject());
        m_out << document.toJson(QJsonDocument::Indented);
        m_out.flush();
    }

    int ports(const Arguments &args, const QStringList &rest)
    {
        allowOnly(args, {}, QStringLiteral("ports"));
        if (!rest.isEmpty())
            throw UsageError {ServoctlTr::tr("ports takes no arguments")};
        const auto available = QSerialPortInfo::availablePorts();
        if (m_json) {
            QJsonArray array;
            for (const QSerialPortInfo &port : available) {
                QJsonObject object {{QStringLiteral("name"), port.portName()},
                                    {QStringLiteral("path"), port.systemLocation()},
                                    {QStringLiteral("description"), port.description()},
                                    {QStringLiteral("manufacturer"), port.manufacturer()},
                                    {QStringLiteral("serial_number"), port.serialNumber()}};
                if (port.hasVendorIdentifier())
                    object.insert(QStringLiteral("vendor_id"), port.vendorIdentifier());
                if (port.hasProductIdentifier())
                    object.insert(QStringLiteral("product_id"), port.productIdentifier());
                array.append(object);
            }
            printJson(array);
            return ExitOk;
        }
        if (available.isEmpty())
            m_out << ServoctlTr::tr("no serial ports found") << '\n';
        for (const QSerialPortInfo &port : available) {
            m_out << port.systemLocation();
            if (!port.description().isEmpty())
                m_out << "  " << port.description();
            m_out << '\n';
        }
        m_out.flush();
        return ExitOk;
    }

    int decode(const Arguments &args, const QStringList &rest)
    {
        allowOnly(args, {QStringLiteral("family"), QStringLiteral("log")},
                  QStringLiteral("decode"));
        if (args.has(QStringLiteral("log")))
            return decodeLog(args, rest);
        if (rest.isEmpty())
            throw UsageError {ServoctlTr::tr("decode needs the bytes to decode, as hex")};
        QString error;
        const auto bytes = util::parseHex(rest, &error);
        if (!bytes)
            throw UsageError {error};
        std::optional<Protocol> protocol;
        if (args.has(QStringLiteral("family"))) {
            const QString family = args.value(QStringLiteral("family"));
            if (family == QLatin1String("ptk"))
                protocol = Protocol::Ptk;
            else if (family == QLatin1String("feetech"))
                protocol = Protocol::Feetech;
            else
                throw UsageError {ServoctlTr::tr("--family must be ptk or feetech")};
        } else {
            protocol = guessProtocol(*bytes);
            if (!protocol)
                throw UsageError {ServoctlTr::tr("no PTK (AF FA) or Feetech (FF FF) header found; "
                                                 "name the protocol with --family")};
        }
        const QVector<DecodedFrame> frames = decodeStream(
            *protocol, *bytes,
            m_json ? seriallink::Detail::SummaryAndFields : seriallink::Detail::Summary);
        if (m_json) {
            QJsonArray array;
            for (const DecodedFrame &frame : frames)
                array.append(toJson(frame));
            printJson(array);
        } else {
            for (const DecodedFrame &frame : frames) {
                m_out << util::toHex(frame.bytes) << '\n' << "    " << frame.summary;
                if (frame.kind != QLatin1String("garbage")
                    && frame.kind != QLatin1String("incomplete"))
                    m_out << (frame.checksumValid ? ServoctlTr::tr(" [checksum ok]")
                                                  : ServoctlTr::tr(" [BAD CHECKSUM]"));
                m_out << '\n';
            }
            m_out.flush();
        }
        return ExitOk;
    }

    // A recording of `servoctl share`, frame by frame: each answer read beside the request it
    // answers (the program's, or ServoBench's own).
    int decodeLog(const Arguments &args, const QStringList &rest)
    {
        if (!rest.isEmpty())
            throw UsageError {ServoctlTr::tr("decode --log takes the recording only, no bytes")};
        if (args.has(QStringLiteral("family"))
            && args.value(QStringLiteral("family")) != QLatin1String("feetech"))
            throw UsageError {
                ServoctlTr::tr("share recordings are of Feetech buses: --family feetech")};
        util::FileError error;
        const auto frames = share::ShareRecording::load(args.value(QStringLiteral("log")), &error);
        if (!frames) {
            m_err << "servoctl: " << error.describe() << '\n';
            m_err.flush();
            return ExitUsage;
        }
        const QVector<QVector<share::RegisterAccess>> keyed = registersByFrame(*frames);
        QByteArray programRequest;
        QByteArray ownRequest;
        QJsonArray array;
        for (qsizetype index = 0; index < frames->size(); ++index) {
            const share::RecordedFrame &frame = frames->at(index);
            const QVector<share::RegisterAccess> &registers = keyed.at(index);
            QString meaning = frame.note;
            switch (frame.direction) {
            case share::FrameDirection::FromProgram:
                programRequest = frame.bytes;
                meaning = feetech::describeFrame(frame.bytes, {});
                break;
            case share::FrameDirection::Own:
                ownRequest = frame.bytes;
                meaning = feetech::describeFrame(frame.bytes, {});
                break;
            case share::FrameDirection::ToProgram:
                meaning = feetech::describeFrame(frame.bytes, programRequest);
                break;
            case share::FrameDirection::OwnAnswer:
                meaning = feetech::describeFrame(frame.bytes, ownRequest);
                break;
            case share::FrameDirection::Note:
                break;
            }
            const QString direction = share::ShareRecording::directionKey(frame.direction);
            const QString time = QString::number(double(frame.timeUs) / 1e6, 'f', 6);
            if (m_json) {
                QJsonObject object {{QStringLiteral("time"), double(frame.timeUs) / 1e6},
                                    {QStringLiteral("direction"), direction},
                                    {QStringLiteral("summary"), meaning}};
                if (frame.direction != share::FrameDirection::Note)
                    object.insert(QStringLiteral("hex"), util::toHex(frame.bytes));
                if (!registers.isEmpty())
                    object.insert(QStringLiteral("registers"), share::registersToJson(registers));
                array.append(object);
            } else if (frame.direction == share::FrameDirection::Note) {
                m_out << time << ' ' << direction << "  " << meaning << '\n';
            } else {
                m_out << time << ' ' << direction << "  " << util::toHex(frame.bytes) << '\n'
                      << "    " << meaning << '\n';
                if (!registers.isEmpty())
                    m_out << "    " << describeRegisters(registers) << '\n';
            }
        }
        if (m_json)
            printJson(array);
        m_out.flush();
        return ExitOk;
    }

    // What each frame of a recording read or wrote, by key, as the share named it while it
    // ran: the frames replayed, transaction by transaction, through what it learns of servos.
    static QVector<QVector<share::RegisterAccess>>
    registersByFrame(const QVector<share::RecordedFrame> &frames)
    {
        QVector<QVector<share::RegisterAccess>> keyed(frames.size());
        share::ObservedServos servos;
        struct Open
        {
            qsizetype request = -1;
            share::SharedTransaction transaction;
            QHash<quint8, qsizetype> replies; // a reply's frame by the ID that sent it
        };
        Open program;
        Open own;
        const auto finish = [&](Open &open) {
            if (open.request < 0)
                return;
            servos.learn(open.transaction, 0);
            for (const share::RegisterAccess &access : std::as_const(open.transaction.registers)) {
                const qsizetype at =
                    access.written ? open.request : open.replies.value(access.id, -1);
                if (at >= 0)
                    keyed[at].append(access);
            }
            open = {};
        };
        for (qsizetype index = 0; index < frames.size(); ++index) {
            const share::RecordedFrame &frame = frames.at(index);
            const bool ownSide = frame.direction == share::FrameDirection::Own
                || frame.direction == share::FrameDirection::OwnAnswer;
            Open &open = ownSide ? own : program;
            const bool request = frame.direction == share::FrameDirection::FromProgram
                || frame.direction == share::FrameDirection::Own;
            if (frame.direction == share::FrameDirection::Note || frame.bytes.size() < 6)
                continue;
            if (request) {
                finish(open);
                open.request = index;
                open.transaction.request = frame.bytes;
            } else if (open.request >= 0 && frame.bytes != open.transaction.request) {
                open.transaction.replies.append(frame.bytes); // an echo is no answer
                open.replies.insert(quint8(frame.bytes.at(2)), index);
            }
        }
        finish(program);
        finish(own);
        return keyed;
    }

    // "ID 1: lock = 0, torque_enable = 1"; an ID's registers together, IDs in order met.
    static QString describeRegisters(const QVector<share::RegisterAccess> &registers)
    {
        QStringList parts;
        quint8 id = 0;
        for (const share::RegisterAccess &access : registers) {
            const QString value = QStringLiteral("%1 = %2").arg(access.key).arg(access.value);
            if (parts.isEmpty() || access.id != id)
                parts.append(ServoctlTr::tr("ID %1: %2").arg(access.id).arg(value));
            else
                parts.last() += QStringLiteral(", ") + value;
            id = access.id;
        }
        return parts.join(QStringLiteral("; "));
    }

    int printFrames(const QVector<std::pair<QString, QByteArray>> &frames)
    {
        if (m_json) {
            QJsonArray array;
            for (const auto &[name, bytes] : frames)
                array.append(QJsonObject {{QStringLiteral("name"), name},
                                          {QStringLiteral("hex"), util::toHex(bytes)}});
            printJson(array);
        } else {
            for (const auto &frame : frames)
                m_out << util::toHex(frame.second) << '\n';
            m_out.flush();
        }
        return ExitOk;
    }

    int packet(const Arguments &args, const QStringList &rest)
    {
        if (rest.isEmpty())
            throw UsageError {ServoctlTr::tr("packet needs a protocol: ptk or feetech")};
        if (rest.first() == QLatin1String("ptk"))
            return ptkPacket(args, rest.mid(1));
        if (rest.first() == QLatin1String("feetech"))
            return feetechPacket(args, rest.mid(1));
        throw UsageError {
            ServoctlTr::tr("unknown protocol \"%1\": use ptk or feetech").arg(rest.first())};
    }

    int ptkPacket(const Arguments &args, const QStringList &rest)
    {
        allowOnly(args, {}, QStringLiteral("packet ptk"));
        if (rest.isEmpty())
            throw UsageError {ServoctlTr::tr("packet ptk needs query CMD or write NAME=VALUE...")};
        if (rest.first() == QLatin1String("query")) {
            if (rest.size() != 2)
                throw UsageError {ServoctlTr::tr("packet ptk query needs exactly one command")};
            const QString text = rest.at(1);
            for (const ptk::FrameLayout &query : ptk::queryLayouts()) {
                if (text.compare(QLatin1String(query.name), Qt::CaseInsensitive) == 0)
                    return printFrames(
                        {{QLatin1String(query.name), ptk::encodeQuery(query.command)}});
            }
            const auto command = util::parseInteger(text);
            if (!command || *command < 0 || *command > 255)
                throw UsageError {
                    ServoctlTr::tr("\"%1\" is not a command byte (0-255) or N1..N8").arg(text)};
            const ptk::FrameLayout *known = ptk::findQuery(quint8(*command));
            return printFrames({{known ? QLatin1String(known->name) : QString(),
                                 ptk::encodeQuery(quint8(*command))}});
        }
        if (rest.first() == QLatin1String("write"))
            return ptkWrite(rest.mid(1));
        throw UsageError {
            ServoctlTr::tr("unknown PTK packet \"%1\": use query or write").arg(rest.first())};
    }

    int ptkWrite(const QStringList &assignments)
    {
        if (assignments.isEmpty())
            throw UsageError {ServoctlTr::tr("packet ptk write needs NAME=VALUE arguments")};
        const ptk::ParameterSet values = parsePtkAssignments(assignments);
        // Every frame that carries a named value; the whole sequence (N10 included) when every
        // parameter is named, as PTK's software sends it.
        QVector<std::pair<QString, QByteArray>> frames;
        const bool complete = values.isComplete();
        for (const ptk::FrameLayout &layout : ptk::writeLayouts()) {
            const bool carries = (layout.word0 && values.has(*layout.word0))
                || (layout.word1 && values.has(*layout.word1));
            if (!carries && !complete)
                continue;
            const auto request = ptk::writeRequest(layout, values);
            if (!request) {
                const auto missing =
                    layout.word0 && !values.has(*layout.word0) ? *layout.word0 : *layout.word1;
                throw UsageError {
                    ServoctlTr::tr("write %1 also carries %2; give it too")
                        .arg(QLatin1String(layout.name), QLatin1String(ptk::info(missing).key))};
            }
            frames.append({QLatin1String(layout.name), ptk::encodeRequest(*request)});
        }
        return printFrames(frames);
    }

    int feetechPacket(const Arguments &args, const QStringList &rest)
    {
        if (rest.size() != 1)
            throw UsageError {
                ServoctlTr::tr("packet feetech needs one instruction (try servoctl --help)")};
        const QString name = rest.first();
        const QString what = QStringLiteral("packet feetech ") + name;
        const auto id = [&](bool unicastOnly, std::optional<int> fallback = std::nullopt) {
            if (!args.has(QStringLiteral("id"))) {
                if (fallback)
                    return quint8(*fallback);
                throw UsageError {ServoctlTr::tr("%1 needs --id").arg(what)};
            }
            if (unicastOnly) {
                const auto value = util::parseInteger(args.value(QStringLiteral("id")));
                if (value && *value > feetech::kMaxServoId && *value <= 255)
                    throw UsageError {ServoctlTr::tr("%1 needs a unicast ID (0-253), not %2")
                                          .arg(what)
                                          .arg(*value)};
            }
            return quint8(integerOption(args, QStringLiteral("id"), 0, feetech::kBroadcastId));
        };
        const auto address = [&]() {
            if (!args.has(QStringLiteral("addr")))
                throw UsageError {ServoctlTr::tr("%1 needs --addr").arg(what)};
            return quint8(integerOption(args, QStringLiteral("addr"), 0, 255));
        };
        const auto data = [&]() {
            if (!args.has(QStringLiteral("data")))
                throw UsageError {ServoctlTr::tr("%1 needs --data").arg(what)};
            const QByteArray bytes = hexOption(args, QStringLiteral("data"));
            if (bytes.isEmpty())
                throw UsageError {ServoctlTr::tr("--data is empty")};
            return bytes;
        };
        const auto length = [&](int maximum) {
            if (!args.has(QStringLiteral("len")))
                throw UsageError {ServoctlTr::tr("%1 needs --len").arg(what)};
            return int(integerOption(args, QStringLiteral("len"), 1, maximum));
        };
        const int maxData = feetech::kMaxPacketSize - feetech::kMinimumPacketSize - 1;
        const auto checkSize = [&](const QByteArray &packet) {
            if (packet.size() > feetech::kMaxPacketSize)
                throw UsageError {ServoctlTr::tr("the packet would be %1 bytes; the limit is %2")
                                      .arg(packet.size())
                                      .arg(feetech::kMaxPacketSize)};
            return printFrames({{name, packet}});
        };

        if (name == QLatin1String("ping")) {
            allowOnly(args, {QStringLiteral("id")}, what);
            return checkSize(feetech::ping(id(false)));
        }
        if (name == QLatin1String("read")) {
            allowOnly(args, {QStringLiteral("id"), QStringLiteral("addr"), QStringLiteral("len")},
                      what);
            const quint8 target = id(true);
            const quint8 start = address();
            return checkSize(feetech::read(target, start, quint8(length(maxData))));
        }
        if (name == QLatin1String("write") || name == QLatin1String("reg-write")) {
            allowOnly(args, {QStringLiteral("id"), QStringLiteral("addr"), QStringLiteral("data")},
                      what);
            const quint8 target = id(false);
            const quint8 start = address();
            const QByteArray bytes = data();
            return checkSize(name == QLatin1String("write")
                                 ? feetech::write(target, start, bytes)
                                 : feetech::regWrite(target, start, bytes));
        }
        if (name == QLatin1String("action")) {
            allowOnly(args, {QStringLiteral("id")}, what);
            return checkSize(feetech::action(id(false, feetech::kBroadcastId)));
        }
        if (name == QLatin1String("recovery") || name == QLatin1String("reboot")
            || name == QLatin1String("reset")) {
            allowOnly(args, {QStringLiteral("id")}, what);
            const quint8 target = id(false);
            if (name == QLatin1String("recovery"))
                return checkSize(feetech::recovery(target));
            return checkSize(name == QLatin1String("reboot") ? feetech::reboot(target)
                                                             : feetech::reset(target));
        }
        if (name == QLatin1String("calibrate")) {
            allowOnly(args, {QStringLiteral("id"), QStringLiteral("data")}, what);
            const quint8 target = id(false);
            QByteArray position;
            if (args.has(QStringLiteral("data"))) {
                position = data();
                if (position.size() != 2)
                    throw UsageError {ServoctlTr::tr(
                        "calibrate --data is a 2-byte position in the family's byte order")};
            }
            return checkSize(feetech::calibrate(target, position));
        }
        if (name == QLatin1String("sync-read")) {
            allowOnly(args, {QStringLiteral("addr"), QStringLiteral("len"), QStringLiteral("ids")},
                      what);
            if (!args.has(QStringLiteral("ids")))
                throw UsageError {ServoctlTr::tr("%1 needs --ids").arg(what)};
            const quint8 start = address();
            const int count = length(maxData);
            return checkSize(
                feetech::syncRead(start, quint8(count),
                                  idList(args.value(QStringLiteral("ids")), feetech::kMaxServoId)));
        }
        if (name == QLatin1String("sync-write")) {
            allowOnly(args,
                      {QStringLiteral("addr"), QStringLiteral("len"), QStringLiteral("ids"),
                       QStringLiteral("data")},
                      what);
            if (!args.has(QStringLiteral("ids")))
                throw UsageError {ServoctlTr::tr("%1 needs --ids").arg(what)};
            const quint8 start = address();
            const QVector<quint8> ids =
                idList(args.value(QStringLiteral("ids")), feetech::kMaxServoId);
            const QByteArray bytes = data();
            // --data holds one block that every servo gets, or with --len one block per servo.
            const int blockSize =
                args.has(QStringLiteral("len")) ? length(maxData) : int(bytes.size());
            const bool shared = bytes.size() == blockSize;
            if (!shared && bytes.size() != blockSize * ids.size())
                throw UsageError {
                    ServoctlTr::tr("--data must hold %1 or %2 bytes (--len %1 for %3 servos)")
                        .arg(blockSize)
                        .arg(blockSize * ids.size())
                        .arg(ids.size())};
            QVector<feetech::SyncWriteEntry> entries;
            for (int i = 0; i < ids.size(); ++i)
                entries.append({ids.at(i), shared ? bytes : bytes.mid(i * blockSize, blockSize)});
            const auto packet = feetech::syncWrite(start, quint8(blockSize), entries);
            if (!packet)
                throw UsageError {ServoctlTr::tr("the SYNC WRITE would exceed %1 bytes")
                                      .arg(feetech::kMaxPacketSize)};
            return checkSize(*packet);
        }
        throw UsageError {
            ServoctlTr::tr("unknown Feetech instruction \"%1\" (try servoctl --help)").arg(name)};
    }

    QTextStream &m_out;
    QTextStream &m_err;
    bool m_json = false;
};

} // namespace

int runServoctl(const QStringList &arguments, QTextStream &out, QTextStream &err)
{
    return Servoctl(out, err).run(arguments);
}

} // namespace cli
