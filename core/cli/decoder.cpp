// Packet decoder for `servoctl decode`: PTK and Feetech frames with their meaning.
#include "cli/decoder.h"

#include "feetech/feetechpacket.h"
#include "ptk/ptkparameters.h"
#include "util/hex.h"

#include <QCoreApplication>
#include <QJsonArray>
#include <QSet>

namespace cli {

namespace {

// Translation context for the messages of this file.
struct Tr
{
    Q_DECLARE_TR_FUNCTIONS(Decoder)
};

QString hexByte(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(2, u'0').toUpper();
}

DecodedFrame stray(const seriallink::StreamItem &item)
{
    DecodedFrame frame;
    frame.kind = QStringLiteral("garbage");
    frame.bytes = item.bytes;
    frame.offset = item.offset;
    frame.checksumValid = false;
    frame.summary = item.kind == seriallink::StreamItem::Kind::Incomplete
        ? Tr::tr("incomplete frame (%n byte(s))", nullptr, int(item.bytes.size()))
        : Tr::tr("%n byte(s) that are not part of any frame", nullptr, int(item.bytes.size()));
    if (item.kind == seriallink::StreamItem::Kind::Incomplete)
        frame.kind = QStringLiteral("incomplete");
    return frame;
}

template<typename Handler>
QVector<DecodedFrame> split(const seriallink::FrameFormat &format, const QByteArray &stream,
                            Handler handleFrame)
{
    seriallink::StreamFramer framer(format,
                                    seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame);
    framer.append(stream);
    QVector<DecodedFrame> frames;
    while (auto item = framer.next()) {
        if (item->kind == seriallink::StreamItem::Kind::Garbage)
            frames.append(stray(*item));
        else
            frames.append(handleFrame(*item));
    }
    if (auto rest = framer.flush())
        frames.append(stray(*rest));
    return frames;
}

QString describeWords(const ptk::FrameLayout &layout, quint16 word0, quint16 word1,
                      QJsonObject &values)
{
    QStringList parts;
    for (const auto &[slot, word] :
         {std::pair {layout.word0, word0}, std::pair {layout.word1, word1}}) {
        if (!slot)
            continue;
        const ptk::ParameterInfo &meta = ptk::info(*slot);
        const double value = ptk::toUserValue(*slot, word);
        values.insert(QLatin1String(meta.key), value);
        parts.append(QStringLiteral("%1=%2").arg(QLatin1String(meta.key)).arg(value));
    }
    return parts.join(u' ');
}

QVector<DecodedFrame> decodePtk(const QByteArray &stream)
{
    const ptk::FrameFormat format;
    const ptk::FrameLayout *lastQuery = nullptr;
    return split(format, stream, [&](const seriallink::StreamItem &item) {
        DecodedFrame frame;
        frame.bytes = item.bytes;
        frame.offset = item.offset;
        frame.checksumValid = item.kind == seriallink::StreamItem::Kind::Frame;
        QJsonObject values;
        const QByteArray &b = item.bytes;
        const auto word = [&](int index) {
            return ptk::wordAt(b, index);
        };
        if (b.size() == ptk::kRequestSize) {
            const quint8 command = quint8(b[4]);
            frame.fields.insert(QStringLiteral("command"), command);
            frame.fields.insert(QStringLiteral("payload"), QJsonArray {word(5), word(7)});
            if (const ptk::FrameLayout *query = ptk::findQuery(command)) {
                frame.kind = QStringLiteral("query");
                frame.fields.insert(QStringLiteral("name"), QLatin1String(query->name));
                QStringList asks;
                for (const auto slot : {query->word0, query->word1}) {
                    if (slot)
                        asks.append(QLatin1String(ptk::info(*slot).key));
                }
                frame.summary = Tr::tr("query %1 (command %2) asks for %3")
                                    .arg(QLatin1String(query->name), hexByte(command),
                                         asks.join(QStringLiteral(", ")));
                lastQuery = frame.checksumValid ? query : nullptr;
            } else if (const ptk::FrameLayout *write = ptk::findWrite(command)) {
                frame.kind = QStringLiteral("write");
                frame.fields.insert(QStringLiteral("name"), QLatin1String(write->name));
                const QString what = describeWords(*write, word(5), word(7), values);
                frame.summary = Tr::tr("write %1 (command %2) %3")
                                    .arg(QLatin1String(write->name), hexByte(command),
                                         what.isEmpty() ? Tr::tr("with zero payload") : what);
                lastQuery = nullptr;
            } else {
                frame.kind = QStringLiteral("request");
                frame.summary = Tr::tr("request with unknown command %1, payload %2 %3")
                                    .arg(hexByte(command))
                                    .arg(word(5))
                                    .arg(word(7));
                lastQuery = nullptr;
            }
        } else {
            frame.kind = QStringLiteral("reply");
            frame.fields.insert(QStringLiteral("payload"), QJsonArray {word(4), word(6)});
            if (lastQuery) {
                frame.fields.insert(QStringLiteral("answers"), QLatin1String(lastQuery->name));
                frame.summary = Tr::tr("reply to %1: %2")
                                    .arg(QLatin1String(lastQuery->name),
                                         describeWords(*lastQuery, word(4), word(6), values));
            } else {
                frame.summary =
                    Tr::tr("reply (query unknown): words %1, %2").arg(word(4)).arg(word(6));
            }
            lastQuery = nullptr;
        }
        if (!values.isEmpty())
            frame.fields.insert(QStringLiteral("values"), values);
        return frame;
    });
}

QString idText(quint8 id)
{
    return id == feetech::kBroadcastId ? Tr::tr("ID %1 (broadcast)").arg(id)
                                       : Tr::tr("ID %1").arg(id);
}

QVector<DecodedFrame> decodeFeetech(const QByteArray &stream)
{
    const feetech::FrameFormat format;
    QSet<int> expectedReplies; // servos the last instruction asked to answer (-1: any)
    return split(format, stream, [&](const seriallink::StreamItem &item) {
        DecodedFrame frame;
        frame.bytes = item.bytes;
        frame.offset = item.offset;
        frame.checksumValid = item.kind == seriallink::StreamItem::Kind::Frame;
        const quint8 id = quint8(item.bytes[2]);
        const quint8 code = quint8(item.bytes[4]);
        const QByteArray params = item.bytes.mid(5, item.bytes.size() - 6);
        frame.fields.insert(QStringLiteral("id"), id);
        const auto instruction = feetech::instructionName(code);
        const bool isReply = expectedReplies.contains(id) || expectedReplies.contains(-1);
        if (isReply || !instruction) {
            expectedReplies.remove(id);
            frame.kind = QStringLiteral("status");
            frame.fields.insert(QStringLiteral("error"), code);
            const QStringList bits = feetech::statusBitNames(code);
            frame.fields.insert(QStringLiteral("error_bits"), QJsonArray::fromStringList(bits));
            frame.fields.insert(QStringLiteral("data"), util::toHex(params));
            frame.summary =
                Tr::tr("status from %1: %2")
                    .arg(idText(id),
                         code == 0 ? Tr::tr("no error")
                                   : Tr::tr("error %1 (%2)")
                                         .arg(hexByte(code), bits.join(QStringLiteral(", "))));
            if (!params.isEmpty())
                frame.summary += Tr::tr(", data %1").arg(util::toHex(params));
            return frame;
        }
        frame.kind = QStringLiteral("instruction");
        frame.fields.insert(QStringLiteral("instruction"), *instruction);
        frame.fields.insert(QStringLiteral("instruction_code"), code);
        frame.fields.insert(QStringLiteral("parameters"), util::toHex(params));
        QString detail;
        const auto address = [&]() {
            return params.isEmpty() ? quint8(0) : quint8(params[0]);
        };
        switch (feetech::Instruction(code)) {
        case feetech::Instruction::Read:
            if (params.size() == 2)
                detail = Tr::tr("address %1 (%2), length %3")
                             .arg(address())
                             .arg(hexByte(address()))
                             .arg(quint8(params[1]));
            break;
        case feetech::Instruction::Write:
        case feetech::Instruction::RegWrite:
            if (!params.isEmpty())
                detail = Tr::tr("address %1 (%2), data %3")
                             .arg(address())
                             .arg(hexByte(address()))
                             .arg(util::toHex(params.mid(1)));
            break;
        case feetech::Instruction::SyncRead:
            if (params.size() >= 2) {
                QStringList ids;
                for (int i = 2; i < params.size(); ++i) {
                    ids.append(QString::number(quint8(params[i])));
                    if (frame.checksumValid)
                        expectedReplies.insert(quint8(params[i]));
                }
                detail = Tr::tr("address %1 (%2), length %3, IDs %4")
                             .arg(address())
                             .arg(hexByte(address()))
                             .arg(quint8(params[1]))
                             .arg(ids.join(u','));
            }
            break;
        case feetech::Instruction::SyncWrite:
            if (params.size() >= 2) {
                const int length = quint8(params[1]);
                QStringList entries;
                for (int i = 2; length > 0 && i + length < params.size(); i += length + 1)
                    entries.append(Tr::tr("ID %1: %2")
                                       .arg(quint8(params[i]))
                                       .arg(util::toHex(params.mid(i + 1, length))));
                detail = Tr::tr("address %1 (%2), length %3; %4")
                             .arg(address())
                             .arg(hexByte(address()))
                             .arg(length)
                             .arg(entries.join(QStringLiteral("; ")));
            }
            break;
        case feetech::Instruction::Calibrate:
            detail = params.isEmpty()
                ? Tr::tr("current position becomes the middle")
                : Tr::tr("current position becomes %1").arg(util::toHex(params));
            break;
        default:
            if (!params.isEmpty())
                detail = Tr::tr("parameters %1").arg(util::toHex(params));
            break;
        }
        frame.summary =
            *instruction + u' ' + idText(id) + (detail.isEmpty() ? QString() : u' ' + detail);
        // Which frames that follow are replies: unicast instructions get one from their servo
        // (ACTION and REBOOT never answer), a broadcast PING from anyone.
        const auto kind = feetech::Instruction(code);
        if (frame.checksumValid && kind != feetech::Instruction::SyncRead) {
            expectedReplies.clear();
            if (id == feetech::kBroadcastId) {
                if (kind == feetech::Instruction::Ping)
                    expectedReplies.insert(-1);
            } else if (kind != feetech::Instruction::Reboot
                       && kind != feetech::Instruction::SyncWrite) {
                expectedReplies.insert(id);
            }
        }
        return frame;
    });
}

} // namespace

std::optional<Protocol> guessProtocol(const QByteArray &stream)
{
    for (int i = 0; i + 1 < stream.size(); ++i) {
        if (quint8(stream[i]) == ptk::kHeader0 && quint8(stream[i + 1]) == ptk::kHeader1)
            return Protocol::Ptk;
        if (quint8(stream[i]) == 0xFF && quint8(stream[i + 1]) == 0xFF)
            return Protocol::Feetech;
    }
    return std::nullopt;
}

QVector<DecodedFrame> decodeStream(Protocol protocol, const QByteArray &stream)
{
    return protocol == Protocol::Ptk ? decodePtk(stream) : decodeFeetech(stream);
}

QJsonObject toJson(const DecodedFrame &frame)
{
    QJsonObject object = frame.fields;
    object.insert(QStringLiteral("kind"), frame.kind);
    object.insert(QStringLiteral("offset"), frame.offset);
    object.insert(QStringLiteral("hex"), util::toHex(frame.bytes));
    object.insert(QStringLiteral("checksum_valid"), frame.checksumValid);
    object.insert(QStringLiteral("summary"), frame.summary);
    return object;
}

} // namespace cli
