// Stream splitting and stray-byte entries shared by the PTK and Feetech frame explanations.
#include "framedescription.h"

#include <QCoreApplication>

namespace {

// The context the decoder's messages have always been translated in.
struct DecoderTr
{
    Q_DECLARE_TR_FUNCTIONS(Decoder)
};

} // namespace

namespace seriallink {

namespace {

DecodedFrame stray(const StreamItem &item)
{
    DecodedFrame frame;
    frame.kind = QStringLiteral("garbage");
    frame.bytes = item.bytes;
    frame.offset = item.offset;
    frame.checksumValid = false;
    frame.summary = item.kind == StreamItem::Kind::Incomplete
        ? DecoderTr::tr("incomplete frame (%n byte(s))", nullptr, int(item.bytes.size()))
        : DecoderTr::tr("%n byte(s) that are not part of any frame", nullptr,
                        int(item.bytes.size()));
    if (item.kind == StreamItem::Kind::Incomplete)
        frame.kind = QStringLiteral("incomplete");
    return frame;
}

} // namespace

QVector<DecodedFrame>
describeStream(const FrameFormat &format, const QByteArray &stream,
               const std::function<DecodedFrame(const StreamItem &item)> &describeFrame)
{
    StreamFramer framer(format, StreamFramer::BadChecksumPolicy::ConsumeFrame);
    framer.append(stream);
    QVector<DecodedFrame> frames;
    while (auto item = framer.next()) {
        if (item->kind == StreamItem::Kind::Garbage)
            frames.append(stray(*item));
        else
            frames.append(describeFrame(*item));
    }
    if (auto rest = framer.flush())
        frames.append(stray(*rest));
    return frames;
}

QString hexByte(int value)
{
    return QStringLiteral("0x") + QString::number(value, 16).rightJustified(2, u'0').toUpper();
}

} // namespace seriallink
