// The framer targets' shared check: one stream through seriallink::StreamFramer whole and in
// pieces, under both bad-checksum policies, with what every item must satisfy.
#pragma once

#include "fuzztarget.h"
#include "streamframer.h"

#include <algorithm>
#include <functional>
#include <vector>

namespace fuzz {

// Every item a framer handed out for one stream, with its counters at the end.
struct FramedStream
{
    std::vector<seriallink::StreamItem> items;
    qint64 framesAccepted = 0;
    qint64 checksumErrors = 0;
    qint64 bytesDiscarded = 0;
};

// Feeds `stream` in pieces of the sizes `pieceSizes` cycles through (the whole stream at once
// when it is empty), takes every item after each piece, then flushes. Checks as it goes that
// items tile the stream: each starts where the bytes consumed so far end, holds exactly the
// stream's bytes there, and what is consumed plus what is pending is what was given.
inline FramedStream frame(const seriallink::FrameFormat &format,
                          seriallink::StreamFramer::BadChecksumPolicy policy,
                          const QByteArray &stream, const QByteArray &pieceSizes)
{
    using Kind = seriallink::StreamItem::Kind;
    seriallink::StreamFramer framer(format, policy);
    FramedStream framed;
    qint64 consumed = 0;
    qint64 given = 0;
    const auto takeItems = [&] {
        while (auto item = framer.next()) {
            FUZZ_CHECK(item->kind != Kind::Incomplete); // only flush() says that
            FUZZ_CHECK(!item->bytes.isEmpty());
            FUZZ_CHECK(item->offset == consumed);
            FUZZ_CHECK(item->offset + item->bytes.size() <= given);
            FUZZ_CHECK(item->bytes == stream.mid(item->offset, item->bytes.size()));
            // A resynchronising framer reports a bad candidate whole but drops only its first
            // byte: a real frame may start inside it.
            const bool dropsOneByte = item->kind == Kind::BadChecksum
                && policy == seriallink::StreamFramer::BadChecksumPolicy::Resync;
            consumed += dropsOneByte ? 1 : item->bytes.size();
            FUZZ_CHECK(consumed + framer.pendingBytes() == given);
            framed.items.push_back(*item);
        }
        FUZZ_CHECK(consumed + framer.pendingBytes() == given);
    };
    qsizetype at = 0;
    int piece = 0;
    while (at < stream.size()) {
        const qsizetype size = pieceSizes.isEmpty()
            ? stream.size()
            : 1 + quint8(pieceSizes.at(piece++ % pieceSizes.size())) % 64;
        const QByteArrayView bytes =
            QByteArrayView(stream).sliced(at).first(std::min<qsizetype>(size, stream.size() - at));
        framer.append(bytes);
        at += bytes.size();
        given += bytes.size();
        takeItems();
    }
    if (auto rest = framer.flush()) {
        FUZZ_CHECK(rest->kind == Kind::Incomplete);
        FUZZ_CHECK(rest->offset == consumed);
        FUZZ_CHECK(rest->bytes == stream.mid(consumed));
        consumed += rest->bytes.size();
        framed.items.push_back(*rest);
    }
    FUZZ_CHECK(consumed == stream.size());
    FUZZ_CHECK(framer.pendingBytes() == 0);
    FUZZ_CHECK(!framer.next().has_value());

    // The counters agree with the items.
    qint64 frames = 0;
    qint64 badChecksums = 0;
    qint64 discarded = 0;
    for (const seriallink::StreamItem &item : framed.items) {
        switch (item.kind) {
        case Kind::Frame:
            ++frames;
            break;
        case Kind::BadChecksum:
            ++badChecksums;
            discarded += policy == seriallink::StreamFramer::BadChecksumPolicy::Resync
                ? 1
                : item.bytes.size();
            break;
        case Kind::Garbage:
        case Kind::Incomplete:
            discarded += item.bytes.size();
            break;
        }
    }
    framed.framesAccepted = framer.framesAccepted();
    framed.checksumErrors = framer.checksumErrors();
    framed.bytesDiscarded = framer.bytesDiscarded();
    FUZZ_CHECK(framed.framesAccepted == frames);
    FUZZ_CHECK(framed.checksumErrors == badChecksums);
    FUZZ_CHECK(framed.bytesDiscarded == discarded);
    return framed;
}

// How the bytes arrive must not change what the framer finds: the frames and bad candidates
// (kind, place, bytes) are the same whole or in pieces; only runs of garbage may be cut
// differently, so they are compared by total.
inline void checkSameFrames(const FramedStream &whole, const FramedStream &pieces)
{
    using Kind = seriallink::StreamItem::Kind;
    const auto framesOf = [](const FramedStream &framed) {
        std::vector<seriallink::StreamItem> frames;
        for (const seriallink::StreamItem &item : framed.items) {
            if (item.kind != Kind::Garbage)
                frames.push_back(item);
        }
        return frames;
    };
    const auto wholeFrames = framesOf(whole);
    const auto pieceFrames = framesOf(pieces);
    FUZZ_CHECK(wholeFrames.size() == pieceFrames.size());
    for (std::size_t i = 0; i < wholeFrames.size(); ++i) {
        FUZZ_CHECK(wholeFrames[i].kind == pieceFrames[i].kind);
        FUZZ_CHECK(wholeFrames[i].offset == pieceFrames[i].offset);
        FUZZ_CHECK(wholeFrames[i].bytes == pieceFrames[i].bytes);
    }
    FUZZ_CHECK(whole.bytesDiscarded == pieces.bytesDiscarded);
}

// The whole check for one family: the input's first byte says how many of the next bytes are
// piece sizes, the rest is the stream. Each frame found must be one the format accepts and
// `reencodes` to exactly its bytes.
inline void checkFramer(const seriallink::FrameFormat &format, const std::uint8_t *data,
                        std::size_t size,
                        const std::function<bool(const QByteArray &frame)> &reencodes)
{
    if (size == 0)
        return;
    const QByteArray all = input(data, size);
    const qsizetype pieceCount = std::min<qsizetype>(quint8(all.at(0)) % 8, all.size() - 1);
    const QByteArray pieceSizes = all.mid(1, pieceCount);
    const QByteArray stream = all.mid(1 + pieceCount);
    for (const auto policy : {seriallink::StreamFramer::BadChecksumPolicy::Resync,
                              seriallink::StreamFramer::BadChecksumPolicy::ConsumeFrame}) {
        const FramedStream whole = frame(format, policy, stream, {});
        for (const seriallink::StreamItem &item : whole.items) {
            if (item.kind != seriallink::StreamItem::Kind::Frame)
                continue;
            FUZZ_CHECK(format.frameLength(item.bytes) == item.bytes.size());
            FUZZ_CHECK(format.checksumValid(item.bytes));
            FUZZ_CHECK(reencodes(item.bytes));
        }
        if (!pieceSizes.isEmpty())
            checkSameFrames(whole, frame(format, policy, stream, pieceSizes));
    }
}

} // namespace fuzz
