// PTK frame explanation: which query, write or reply a frame is and the parameter values it holds.
#include "ptkdescription.h"

#include "ptkparameters.h"

#include <QCoreApplication>
#include <QJsonArray>

namespace {

// The context the decoder's messages have always been translated in.
struct DecoderTr
{
    Q_DECLARE_TR_FUNCTIONS(Decoder)
};

} // namespace

namespace ptk {

namespace {

using seriallink::DecodedFrame;
using seriallink::hexByte;
using seriallink::StreamItem;

// Names the words' values; also fills *values when given (servoctl decode --json).
QString describeWords(const FrameLayout &layout, quint16 word0, quint16 word1, QJsonObject *values)
{
    QStringList parts;
    for (const auto &[slot, word] :
         {std::pair {layout.word0, word0}, std::pair {layout.word1, word1}}) {
        if (!slot)
            continue;
        const ParameterInfo &meta = info(*slot);
        const double value = toUserValue(*slot, word);
        if (values)
            values->insert(QLatin1String(meta.key), value);
        parts.append(QStringLiteral("%1=%2").arg(QLatin1String(meta.key)).arg(value));
    }
    return parts.join(u' ');
}

// Explains one request (query, write or unknown command); remembers a valid query in *lastQuery
// for the reply that follows it. Fields and values are filled only when `values` is given.
void describeRequest(DecodedFrame &frame, QJsonObject *values, const FrameLayout *&lastQuery)
{
    const QByteArray &b = frame.bytes;
    const quint8 command = quint8(b[4]);
    if (values) {
        frame.fields.insert(QStringLiteral("command"), command);
        frame.fields.insert(QStringLiteral("payload"), QJsonArray {wordAt(b, 5), wordAt(b, 7)});
    }
    lastQuery = nullptr;
    if (const FrameLayout *query = findQuery(command)) {
        frame.kind = QStringLiteral("query");
        if (values)
            frame.fields.insert(QStringLiteral("name"), QLatin1String(query->name));
        QStringList asks;
        for (const auto slot : {query->word0, query->word1}) {
            if (slot)
                asks.append(QLatin1String(info(*slot).key));
        }
        frame.summary =
            DecoderTr::tr("query %1 (command %2) asks for %3")
                .arg(QLatin1String(query->name), hexByte(command), asks.join(QStringLiteral(", ")));
        if (frame.checksumValid)
            lastQuery = query;
    } else if (const FrameLayout *write = findWrite(command)) {
        frame.kind = QStringLiteral("write");
        if (values)
            frame.fields.insert(QStringLiteral("name"), QLatin1String(write->name));
        const QString what = describeWords(*write, wordAt(b, 5), wordAt(b, 7), values);
        frame.summary = DecoderTr::tr("write %1 (command %2) %3")
                            .arg(QLatin1String(write->name), hexByte(command),
                                 what.isEmpty() ? DecoderTr::tr("with zero payload") : what);
    } else {
        frame.kind = QStringLiteral("request");
        frame.summary = DecoderTr::tr("request with unknown command %1, payload %2 %3")
                            .arg(hexByte(command))
                            .arg(wordAt(b, 5))
                            .arg(wordAt(b, 7));
    }
}

void describeReply(DecodedFrame &frame, QJsonObject *values, const FrameLayout *query)
{
    const QByteArray &b = frame.bytes;
    frame.kind = QStringLiteral("reply");
    if (values)
        frame.fields.insert(QStringLiteral("payload"), QJsonArray {wordAt(b, 4), wordAt(b, 6)});
    if (query) {
        if (values)
            frame.fields.insert(QStringLiteral("answers"), QLatin1String(query->name));
        frame.summary = DecoderTr::tr("reply to %1: %2")
                            .arg(QLatin1String(query->name),
                                 describeWords(*query, wordAt(b, 4), wordAt(b, 6), values));
    } else {
        frame.summary = DecoderTr::tr("reply (query unknown): words %1, %2")
                            .arg(wordAt(b, 4))
                            .arg(wordAt(b, 6));
    }
}

} // namespace

QVector<DecodedFrame> decodeStream(const QByteArray &stream, seriallink::Detail detail)
{
    const bool withFields = detail == seriallink::Detail::SummaryAndFields;
    const FrameFormat format;
    const FrameLayout *lastQuery = nullptr;
    return seriallink::describeStream(format, stream, [&](const StreamItem &item) {
        DecodedFrame frame;
        frame.bytes = item.bytes;
        frame.offset = item.offset;
        frame.checksumValid = item.kind == StreamItem::Kind::Frame;
        QJsonObject values;
        if (item.bytes.size() == kRequestSize) {
            describeRequest(frame, withFields ? &values : nullptr, lastQuery);
        } else {
            describeReply(frame, withFields ? &values : nullptr, lastQuery);
            lastQuery = nullptr;
        }
        if (!values.isEmpty())
            frame.fields.insert(QStringLiteral("values"), values);
        return frame;
    });
}

QString describeFrame(const QByteArray &frame, const QByteArray &request)
{
    const bool isReply = frame.size() == kReplySize && request.size() == kRequestSize;
    const auto frames =
        decodeStream(isReply ? request + frame : frame, seriallink::Detail::Summary);
    return frames.isEmpty() ? QString() : frames.last().summary;
}

} // namespace ptk
