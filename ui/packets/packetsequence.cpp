// Frames built in the packet window: how each is answered, what makes one risky, and the
// sequence files that keep them.
#include "packetsequence.h"

#include "feetechdescription.h"
#include "feetechpacket.h"
#include "hex.h"
#include "jsonfile.h"
#include "modeltable.h"
#include "ptkdescription.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "registertable.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

namespace {

struct PacketSequenceTr
{
    Q_DECLARE_TR_FUNCTIONS(PacketSequence)
};

constexpr char kFormatMarker[] = "servobench-packets";
constexpr int kFormatVersion = 1;
constexpr char kFramesKey[] = "frames";
constexpr char kProtocolKey[] = "protocol";
constexpr char kBaudKey[] = "baud";
constexpr char kHexKey[] = "hex";
constexpr int kMaxFrames = 1000;

using feetech::Instruction;

util::JsonFormat sequenceFormat()
{
    return {
        kFormatMarker,
        kFormatVersion,
        {kFramesKey},
        PacketSequenceTr::tr(
            "not a ServoBench packet sequence (the document is not a JSON object)"),
        PacketSequenceTr::tr("not a ServoBench packet sequence (\"%1\" is not \"%2\")"),
        PacketSequenceTr::tr("the packet sequence has format version %1 and was written by a newer "
                             "ServoBench; this version reads format version %2 and older")};
}

// The EEPROM registers of any family that bytes [address, address + size) touch, by label.
QStringList eepromRegistersIn(int address, int size)
{
    QStringList names;
    for (const feetech::Family family : feetech::kAllFamilies) {
        for (const feetech::Register &reg : feetech::RegisterTable::forFamily(family).registers()) {
            const QString name = feetech::tableText(reg.label);
            if (reg.overlaps(address, size) && reg.storage == feetech::Storage::Eeprom
                && !names.contains(name))
                names.append(name);
        }
    }
    return names;
}

} // namespace

bool PacketFrame::operator==(const PacketFrame &other) const
{
    return protocol == other.protocol && bytes == other.bytes && baud == other.baud
        && replyId == other.replyId && replyDataSize == other.replyDataSize
        && expectsReply == other.expectsReply;
}

namespace packetsequence {

std::optional<PacketFrame> feetechFrame(const QByteArray &bytes, qint32 baud)
{
    const auto packet = feetech::decodePacket(bytes);
    if (!packet || !feetech::baudCode(baud))
        return std::nullopt;
    PacketFrame frame;
    frame.bytes = bytes;
    frame.baud = baud;
    if (packet->id == feetech::kBroadcastId)
        return frame;
    switch (Instruction(packet->code)) {
    case Instruction::Read:
        if (packet->parameters.size() == 2) {
            frame.replyId = packet->id;
            frame.replyDataSize = quint8(packet->parameters.at(1));
        }
        break;
    case Instruction::Ping:
    case Instruction::Write:
    case Instruction::RegWrite:
    case Instruction::Recovery:
    case Instruction::Reset:
    case Instruction::Calibrate:
        frame.replyId = packet->id;
        break;
    default:
        break; // ACTION, REBOOT, SYNC ... and unknown codes: listened to
    }
    return frame;
}

std::optional<PacketFrame> ptkFrame(const QByteArray &bytes)
{
    const auto request = ptk::decodeRequest(bytes);
    if (!request || bytes.size() != ptk::kRequestSize)
        return std::nullopt;
    PacketFrame frame;
    frame.protocol = PacketFrame::Protocol::Ptk;
    frame.bytes = bytes;
    frame.expectsReply = ptk::findQuery(request->command) != nullptr;
    return frame;
}

QString riskOf(const PacketFrame &frame)
{
    if (frame.protocol == PacketFrame::Protocol::Ptk)
        return frame.expectsReply
            ? QString()
            : PacketSequenceTr::tr(
                "It writes to the PTK servo, outside the verified write sequence of its "
                "settings page.");
    const auto packet = feetech::decodePacket(frame.bytes);
    if (!packet)
        return {};
    const QString who = packet->id == feetech::kBroadcastId
        ? PacketSequenceTr::tr("every servo on the bus")
        : PacketSequenceTr::tr("servo %1").arg(packet->id);
    QStringList written;
    switch (Instruction(packet->code)) {
    case Instruction::Write:
    case Instruction::RegWrite:
        if (!packet->parameters.isEmpty())
            written = eepromRegistersIn(quint8(packet->parameters.at(0)),
                                        int(packet->parameters.size()) - 1);
        break;
    case Instruction::SyncWrite:
        if (packet->parameters.size() >= 2)
            written = eepromRegistersIn(quint8(packet->parameters.at(0)),
                                        quint8(packet->parameters.at(1)));
        break;
    case Instruction::Recovery:
        return PacketSequenceTr::tr("It restores the factory values of %1 (its settings are lost).")
            .arg(who);
    case Instruction::Calibrate:
        return PacketSequenceTr::tr(
                   "It makes the present position the middle of %1 (written to EEPROM).")
            .arg(who);
    case Instruction::Backup:
        return PacketSequenceTr::tr("It asks %1 to store its settings (an EEPROM write).").arg(who);
    default:
        break;
    }
    if (written.isEmpty())
        return {};
    return PacketSequenceTr::tr(
               "It writes %1 of %2, in EEPROM: the servo keeps it when powered off, and a "
               "wrong ID or baud rate makes it answer elsewhere.")
        .arg(written.join(QStringLiteral(", ")), who);
}

QString describe(const PacketFrame &frame)
{
    return frame.protocol == PacketFrame::Protocol::Feetech
        ? feetech::describeFrame(frame.bytes, {})
        : ptk::describeFrame(frame.bytes, {});
}

bool save(const QString &path, const QVector<PacketFrame> &frames, util::FileError *error)
{
    QJsonArray entries;
    for (const PacketFrame &frame : frames) {
        QJsonObject entry {{QLatin1String(kProtocolKey),
                            frame.protocol == PacketFrame::Protocol::Feetech
                                ? QStringLiteral("feetech")
                                : QStringLiteral("ptk")},
                           {QLatin1String(kHexKey), util::toHex(frame.bytes)}};
        if (frame.protocol == PacketFrame::Protocol::Feetech)
            entry.insert(QLatin1String(kBaudKey), frame.baud);
        entries.append(entry);
    }
    const QJsonObject root {{QLatin1String(util::kFormatKey), QLatin1String(kFormatMarker)},
                            {QLatin1String(util::kVersionKey), kFormatVersion},
                            {QLatin1String(kFramesKey), entries}};
    return util::writeFileAtomically(path, QJsonDocument(root).toJson(QJsonDocument::Indented),
                                     error);
}

std::optional<QVector<PacketFrame>> load(const QString &path, util::FileError *error)
{
    using Code = util::FileError::Code;
    util::FileError why;
    const auto fail = [&](util::FileError reason) -> std::optional<QVector<PacketFrame>> {
        util::report(error, reason.inFile(path));
        return std::nullopt;
    };
    const auto failOn = [&](Code code, const QString &reason, const char *field = nullptr) {
        return fail(util::FileError(code, reason).withField(QLatin1String(field)));
    };
    const auto json =
        util::readFile(path, util::kMaxJsonFileBytes,
                       PacketSequenceTr::tr("too large to be a packet sequence"), &why);
    if (!json)
        return fail(why);
    const auto root = util::parseVersionedObject(*json, sequenceFormat(), &why);
    if (!root)
        return fail(why);
    const QJsonValue list = root->value(QLatin1String(kFramesKey));
    if (!list.isArray())
        return failOn(
            Code::WrongType,
            PacketSequenceTr::tr("\"%1\" must be a list of frames").arg(QLatin1String(kFramesKey)),
            kFramesKey);
    const QJsonArray entries = list.toArray();
    if (entries.size() > kMaxFrames)
        return failOn(Code::TooLarge, PacketSequenceTr::tr("more than %1 frames").arg(kMaxFrames),
                      kFramesKey);
    QVector<PacketFrame> frames;
    for (int i = 0; i < entries.size(); ++i) {
        const QJsonObject entry = entries.at(i).toObject();
        if (!entries.at(i).isObject())
            return failOn(
                Code::WrongType,
                PacketSequenceTr::tr("frame %1 is not an object of protocol, hex and baud")
                    .arg(i + 1));
        if (const auto unknown = util::firstUnknownKey(entry, {kProtocolKey, kHexKey, kBaudKey}))
            return fail(util::FileError(Code::UnknownKey,
                                        PacketSequenceTr::tr(
                                            "frame %1 is not an object of protocol, hex and baud")
                                            .arg(i + 1))
                            .withField(*unknown));
        const QString protocol = entry.value(QLatin1String(kProtocolKey)).toString();
        const auto bytes = util::parseHex(entry.value(QLatin1String(kHexKey)).toString());
        if (!bytes)
            return failOn(
                Code::BadValue,
                PacketSequenceTr::tr("frame %1: its hex is not hexadecimal bytes").arg(i + 1),
                kHexKey);
        std::optional<PacketFrame> frame;
        if (protocol == QLatin1String("feetech")) {
            const QJsonValue baud = entry.value(QLatin1String(kBaudKey));
            frame = baud.isDouble() ? feetechFrame(*bytes, baud.toInt()) : std::nullopt;
        } else if (protocol == QLatin1String("ptk")) {
            frame = ptkFrame(*bytes);
        } else {
            return failOn(
                Code::BadValue,
                PacketSequenceTr::tr("frame %1: the protocol must be feetech or ptk").arg(i + 1),
                kProtocolKey);
        }
        if (!frame)
            return failOn(Code::BadValue,
                          PacketSequenceTr::tr("frame %1 is not a whole %2 frame at a known rate")
                              .arg(i + 1)
                              .arg(protocol),
                          kHexKey);
        frames.append(*frame);
    }
    return frames;
}

} // namespace packetsequence
