// One request of a program on a shared bus with its answers: what it asked, and its JSON line.
#include "sharedtransaction.h"

#include "feetechpacket.h"
#include "hex.h"

#include <QJsonArray>

namespace share {

namespace {

// Byte 2 of a frame is its ID, byte 4 the instruction (a request) or the error bits (a status).
constexpr int kIdByte = 2;
constexpr int kCodeByte = 4;
constexpr int kSyncReadIdsFrom = 7; // after header, ID, length, instruction, address, length

} // namespace

quint8 SharedTransaction::id() const
{
    return request.size() > kIdByte ? quint8(request.at(kIdByte)) : 0;
}

quint8 SharedTransaction::instruction() const
{
    return request.size() > kCodeByte ? quint8(request.at(kCodeByte)) : 0;
}

quint8 SharedTransaction::errorBits() const
{
    quint8 bits = 0;
    for (const QByteArray &reply : replies) {
        if (reply.size() > kCodeByte)
            bits |= quint8(reply.at(kCodeByte));
    }
    return bits;
}

bool SharedTransaction::unanswered() const
{
    return expectedReplies > 0 && replies.size() < expectedReplies;
}

QVector<quint8> SharedTransaction::askedIds() const
{
    if (instruction() != quint8(feetech::Instruction::SyncRead))
        return {id()};
    QVector<quint8> ids;
    // The last byte is the checksum.
    for (int i = kSyncReadIdsFrom; i + 1 < request.size(); ++i)
        ids.append(quint8(request.at(i)));
    return ids;
}

QJsonObject SharedTransaction::toJson() const
{
    QJsonObject json;
    json.insert(QStringLiteral("time"), double(timeUs) / 1e6);
    json.insert(QStringLiteral("id"), int(id()));
    json.insert(QStringLiteral("instruction"),
                feetech::instructionName(instruction())
                    .value_or(QStringLiteral("0x%1").arg(instruction(), 2, 16, QLatin1Char('0'))));
    json.insert(QStringLiteral("request"), util::toHex(request));
    QByteArray answered;
    for (const QByteArray &reply : replies)
        answered += reply;
    json.insert(QStringLiteral("reply"), util::toHex(answered));
    json.insert(QStringLiteral("replies"), int(replies.size()));
    json.insert(QStringLiteral("error"), int(errorBits()));
    json.insert(QStringLiteral("error_bits"),
                QJsonArray::fromStringList(feetech::statusBitKeys(errorBits())));
    json.insert(QStringLiteral("round_trip_us"),
                roundTripUs ? QJsonValue(double(*roundTripUs)) : QJsonValue());
    if (unanswered())
        json.insert(QStringLiteral("unanswered"), true);
    if (garbledBytes > 0)
        json.insert(QStringLiteral("garbled_bytes"), garbledBytes);
    if (own)
        json.insert(QStringLiteral("own"), true);
    const QJsonArray meaning = registersToJson(registers);
    if (!meaning.isEmpty())
        json.insert(QStringLiteral("registers"), meaning);
    return json;
}

QJsonArray registersToJson(const QVector<RegisterAccess> &registers)
{
    QJsonArray array;
    for (const RegisterAccess &access : registers) {
        array.append(
            QJsonObject {{QStringLiteral("id"), int(access.id)},
                         {QStringLiteral("key"), access.key},
                         {QStringLiteral("value"), access.value},
                         {QStringLiteral("access"),
                          access.written ? QStringLiteral("write") : QStringLiteral("read")}});
    }
    return array;
}

} // namespace share
