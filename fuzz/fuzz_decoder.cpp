// Fuzz target: `servoctl decode`, from the typed hex text to the explained frames of both
// protocols and their JSON; the frames tile the stream and the hex reads back as it was written.
#include "decoder.h"
#include "fuzztarget.h"
#include "hex.h"

#include <QJsonDocument>

namespace {

// Every byte of the stream is in exactly one frame, garbage or incomplete entry, in order; the
// summary and the fields are the same whether or not the fields were asked for.
void checkDecoded(cli::Protocol protocol, const QByteArray &stream)
{
    const auto frames = cli::decodeStream(protocol, stream);
    qint64 offset = 0;
    for (const cli::DecodedFrame &frame : frames) {
        FUZZ_CHECK(frame.offset == offset);
        FUZZ_CHECK(!frame.bytes.isEmpty());
        FUZZ_CHECK(frame.bytes == stream.mid(offset, frame.bytes.size()));
        FUZZ_CHECK(!frame.kind.isEmpty());
        const QJsonObject json = cli::toJson(frame);
        FUZZ_CHECK(util::parseHex(json.value(QStringLiteral("hex")).toString()) == frame.bytes);
        FUZZ_CHECK(!QJsonDocument(json).toJson(QJsonDocument::Compact).isEmpty());
        offset += frame.bytes.size();
    }
    FUZZ_CHECK(offset == stream.size());

    const auto summaries = cli::decodeStream(protocol, stream, seriallink::Detail::Summary);
    FUZZ_CHECK(summaries.size() == frames.size());
    for (int i = 0; i < frames.size(); ++i) {
        FUZZ_CHECK(summaries[i].kind == frames[i].kind);
        FUZZ_CHECK(summaries[i].summary == frames[i].summary);
        FUZZ_CHECK(summaries[i].checksumValid == frames[i].checksumValid);
    }
}

void checkStream(const QByteArray &stream)
{
    const auto guessed = cli::guessProtocol(stream);
    if (guessed == cli::Protocol::Ptk)
        FUZZ_CHECK(stream.contains("\xAF\xFA"));
    if (guessed == cli::Protocol::Feetech)
        FUZZ_CHECK(stream.contains("\xFF\xFF"));
    checkDecoded(cli::Protocol::Ptk, stream);
    checkDecoded(cli::Protocol::Feetech, stream);
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t *data, std::size_t size)
{
    const QByteArray bytes = fuzz::input(data, size);
    // The input as the bytes captured...
    checkStream(bytes);
    // ...and as the hex text a user types: what parses prints back as the same bytes.
    QString error;
    const auto typed = util::parseHex(QString::fromUtf8(bytes), &error);
    if (!typed) {
        FUZZ_CHECK(!error.isEmpty());
        return 0;
    }
    FUZZ_CHECK(util::parseHex(util::toHex(*typed)) == typed);
    checkStream(*typed);
    return 0;
}
