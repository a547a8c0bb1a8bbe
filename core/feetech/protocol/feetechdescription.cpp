// Feetech packet explanation: instruction parameters, status error bits, and who answers whom.
#include "feetechdescription.h"

#include "feetechpacket.h"
#include "hex.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QSet>

namespace {

// The context the decoder's messages have always been translated in.
struct DecoderTr
{
    Q_DECLARE_TR_FUNCTIONS(Decoder)
};

} // namespace

namespace feetech {

using seriallink::DecodedFrame;
using seriallink::hexByte;
using seriallink::StreamItem;

namespace {

// The instruction as the packet log and decode name it: a language may name it as its own manual
// does (the Chinese one says PING（查询）); JSON keeps instructionName().
QString instructionText(quint8 code, const QString &name)
{
    switch (Instruction(code)) {
    case Instruction::Ping:
        return DecoderTr::tr("PING", "instruction");
    case Instruction::Read:
        return DecoderTr::tr("READ", "instruction");
    case Instruction::Write:
        return DecoderTr::tr("WRITE", "instruction");
    case Instruction::RegWrite:
        return DecoderTr::tr("REG WRITE", "instruction");
    case Instruction::Action:
        return DecoderTr::tr("ACTION", "instruction");
    case Instruction::Recovery:
        return DecoderTr::tr("RECOVERY", "instruction");
    case Instruction::Reboot:
        return DecoderTr::tr("REBOOT", "instruction");
    case Instruction::Backup:
        return DecoderTr::tr("BACKUP", "instruction");
    case Instruction::Reset:
        return DecoderTr::tr("RESET", "instruction");
    case Instruction::Calibrate:
        return DecoderTr::tr("CALIBRATE", "instruction");
    case Instruction::SyncRead:
        return DecoderTr::tr("SYNC READ", "instruction");
    case Instruction::SyncWrite:
        return DecoderTr::tr("SYNC WRITE", "instruction");
    }
    return name;
}

QString idText(quint8 id)
{
    return id == kBroadcastId ? DecoderTr::tr("ID %1 (broadcast)").arg(id)
                              : DecoderTr::tr("ID %1").arg(id);
}

void describeStatus(DecodedFrame &frame, quint8 id, quint8 code, const QByteArray &params,
                    bool withFields)
{
    frame.kind = QStringLiteral("status");
    const QStringList bits = statusBitNames(code);
    if (withFields) {
        frame.fields.insert(QStringLiteral("error"), code);
        frame.fields.insert(QStringLiteral("error_bits"), QJsonArray::fromStringList(bits));
        frame.fields.insert(QStringLiteral("data"), util::toHex(params));
    }
    frame.summary = DecoderTr::tr("status from %1: %2")
                        .arg(idText(id),
                             code == 0 ? DecoderTr::tr("no error")
                                       : DecoderTr::tr("error %1 (%2)")
                                             .arg(hexByte(code), bits.join(QStringLiteral(", "))));
    if (!params.isEmpty())
        frame.summary += DecoderTr::tr(", data %1").arg(util::toHex(params));
}

// The parameters of an instruction in words; SYNC READ also adds the servos it asks to answer.
QString instructionDetail(Instruction instruction, const QByteArray &params, bool checksumValid,
                          QSet<int> &expectedReplies)
{
    const quint8 address = params.isEmpty() ? quint8(0) : quint8(params[0]);
    switch (instruction) {
    case Instruction::Read:
        if (params.size() == 2)
            return DecoderTr::tr("address %1 (%2), length %3")
                .arg(address)
                .arg(hexByte(address))
                .arg(quint8(params[1]));
        break;
    case Instruction::Write:
    case Instruction::RegWrite:
        if (!params.isEmpty())
            return DecoderTr::tr("address %1 (%2), data %3")
                .arg(address)
                .arg(hexByte(address))
                .arg(util::toHex(params.mid(1)));
        break;
    case Instruction::SyncRead:
        if (params.size() >= 2) {
            QStringList ids;
            for (int i = 2; i < params.size(); ++i) {
                ids.append(QString::number(quint8(params[i])));
                if (checksumValid)
                    expectedReplies.insert(quint8(params[i]));
            }
            return DecoderTr::tr("address %1 (%2), length %3, IDs %4")
                .arg(address)
                .arg(hexByte(address))
                .arg(quint8(params[1]))
                .arg(ids.join(u','));
        }
        break;
    case Instruction::SyncWrite:
        if (params.size() >= 2) {
            const int length = quint8(params[1]);
            QStringList entries;
            for (int i = 2; length > 0 && i + length < params.size(); i += length + 1)
                entries.append(DecoderTr::tr("ID %1: %2")
                                   .arg(quint8(params[i]))
                                   .arg(util::toHex(params.mid(i + 1, length))));
            return DecoderTr::tr("address %1 (%2), length %3; %4")
                .arg(address)
                .arg(hexByte(address))
                .arg(length)
                .arg(entries.join(QStringLiteral("; ")));
        }
        break;
    case Instruction::Calibrate:
        return params.isEmpty()
            ? DecoderTr::tr("current position becomes the middle")
            : DecoderTr::tr("current position becomes %1").arg(util::toHex(params));
    default:
        if (!params.isEmpty())
            return DecoderTr::tr("parameters %1").arg(util::toHex(params));
        break;
    }
    return {};
}

// Which frames that follow are replies: unicast instructions get one from their servo (ACTION
// and REBOOT never answer), a broadcast PING from anyone. SYNC READ set its own list above.
void expectRepliesAfter(Instruction instruction, quint8 id, QSet<int> &expectedReplies)
{
    if (instruction == Instruction::SyncRead)
        return;
    expectedReplies.clear();
    if (id == kBroadcastId) {
        if (instruction == Instruction::Ping)
            expectedReplies.insert(-1);
    } else if (instruction != Instruction::Reboot && instruction != Instruction::SyncWrite) {
        expectedReplies.insert(id);
    }
}

} // namespace

QVector<DecodedFrame> decodeStream(const QByteArray &stream, seriallink::Detail detail)
{
    const FrameFormat format;
    const bool withFields = detail == seriallink::Detail::SummaryAndFields;
    QSet<int> expectedReplies; // servos the last instruction asked to answer (-1: any)
    return seriallink::describeStream(format, stream, [&](const StreamItem &item) {
        DecodedFrame frame;
        frame.bytes = item.bytes;
        frame.offset = item.offset;
        frame.checksumValid = item.kind == StreamItem::Kind::Frame;
        const quint8 id = quint8(item.bytes[2]);
        const quint8 code = quint8(item.bytes[4]);
        const QByteArray params = item.bytes.mid(5, item.bytes.size() - 6);
        if (withFields)
            frame.fields.insert(QStringLiteral("id"), id);
        const auto name = instructionName(code);
        const bool isReply = expectedReplies.contains(id) || expectedReplies.contains(-1);
        if (isReply || !name) {
            expectedReplies.remove(id);
            describeStatus(frame, id, code, params, withFields);
            return frame;
        }
        frame.kind = QStringLiteral("instruction");
        if (withFields) {
            frame.fields.insert(QStringLiteral("instruction"), *name);
            frame.fields.insert(QStringLiteral("instruction_code"), code);
            frame.fields.insert(QStringLiteral("parameters"), util::toHex(params));
        }
        const auto instruction = Instruction(code);
        const QString detail =
            instructionDetail(instruction, params, frame.checksumValid, expectedReplies);
        frame.summary = instructionText(code, *name) + u' ' + idText(id)
            + (detail.isEmpty() ? QString() : u' ' + detail);
        if (frame.checksumValid)
            expectRepliesAfter(instruction, id, expectedReplies);
        return frame;
    });
}

QString describeFrame(const QByteArray &frame, const QByteArray &request)
{
    // After its request a frame is an answer, even one with the request's very bytes.
    const auto frames = decodeStream(request + frame, seriallink::Detail::Summary);
    return frames.isEmpty() ? QString() : frames.last().summary;
}

} // namespace feetech
