// Throughput of the byte-level codecs in MB/s: the PTK and Feetech framers fed realistic traffic
// in serial-port-sized chunks, the packet decoders, and the frame decoder behind servoctl decode,
// per second of CPU time.
#include "benchsupport.h"
#include "decoder.h"
#include "feetechdescription.h"
#include "feetechpacket.h"
#include "hex.h"
#include "ptkdescription.h"
#include "ptkframe.h"
#include "ptkparameters.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRandomGenerator>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <optional>

namespace {

constexpr qint64 kMinimumNs = 600'000'000; // each figure runs at least this long
constexpr int kTrafficFrames = 4000; // frames in one pass of the traffic buffer
constexpr int kNoiseEvery = 7; // a run of noise after every seventh frame
constexpr int kMaxNoiseRun = 3;
constexpr int kChunkSizes[] = {1, 32, 4096};
constexpr double kMegabyte = 1e6;

struct Traffic
{
    QByteArray stream;
    QVector<QByteArray> frames; // every valid frame of the stream, in order
    qint64 noiseBytes = 0;
};

// A request and the frames that answer it, as a session sends and hears them.
struct Exchange
{
    QByteArray request;
    QVector<QByteArray> replies;
};

// Frames of the sizes a PTK session sees: the eight queries and their replies, and writes.
QVector<Exchange> ptkExchanges()
{
    QVector<Exchange> exchanges;
    for (const ptk::FrameLayout &query : ptk::queryLayouts())
        exchanges.append({ptk::encodeQuery(query.command), {ptk::encodeReply({0x0320, 0x07D0})}});
    exchanges.append({ptk::encodeRequest({0x48, 0x07D0, 0x2710}), {}});
    exchanges.append({ptk::encodeRequest({0x12, 0x0320, 0x07D0}), {}});
    return exchanges;
}

// Feetech: PING, a READ of the position, a feedback SYNC READ of six servos, a goal WRITE, and a
// full-table block READ (the largest answer a session reads), each with its answers.
QVector<Exchange> feetechExchanges()
{
    QVector<Exchange> exchanges;
    exchanges.append({feetech::ping(1), {feetech::status(1, 0)}});
    exchanges.append(
        {feetech::read(1, 0x38, 2), {feetech::status(1, 0, QByteArray::fromHex("1805"))}});
    Exchange feedback {feetech::syncRead(0x38, 15, {1, 2, 3, 4, 5, 6}), {}};
    for (quint8 id = 1; id <= 6; ++id)
        feedback.replies.append(feetech::status(
            id, 0, QByteArray::fromHex("00080000E803000020007C0100") + QByteArray(2, char(id))));
    exchanges.append(feedback);
    exchanges.append(
        {feetech::write(1, 0x2A, QByteArray::fromHex("00080000E803")), {feetech::status(1, 0)}});
    QByteArray table(70, 0);
    for (int i = 0; i < table.size(); ++i)
        table[i] = char(i * 37);
    exchanges.append({feetech::read(1, 0, 70), {feetech::status(1, 0, table)}});
    return exchanges;
}

// Noise never holds a header byte, so every frame put in must come out and every noise byte
// must be counted as discarded: the figures are checked against the framer's own counts.
Traffic makeTraffic(const QVector<Exchange> &exchanges, const QByteArray &headerBytes)
{
    QVector<QByteArray> kinds;
    for (const Exchange &exchange : exchanges)
        kinds += QVector<QByteArray> {exchange.request} + exchange.replies;
    QRandomGenerator random(20261124);
    Traffic traffic;
    for (int i = 0; i < kTrafficFrames; ++i) {
        const QByteArray &frame = kinds.at(i % kinds.size());
        traffic.stream += frame;
        traffic.frames.append(frame);
        if (i % kNoiseEvery != kNoiseEvery - 1)
            continue;
        const int run = 1 + int(random.bounded(kMaxNoiseRun));
        for (int n = 0; n < run; ++n) {
            char noise = char(random.bounded(256));
            while (headerBytes.contains(noise))
                noise = char(random.bounded(256));
            traffic.stream += noise;
        }
        traffic.noiseBytes += run;
    }
    return traffic;
}

// The chunks point into `stream` (which must outlive them): what is timed is the framer, not
// where the benchmark keeps its input.
QVector<QByteArray> chunked(const QByteArray &stream, int size)
{
    QVector<QByteArray> chunks;
    for (qsizetype at = 0; at < stream.size(); at += size)
        chunks.append(QByteArray::fromRawData(stream.constData() + at,
                                              std::min<qsizetype>(size, stream.size() - at)));
    return chunks;
}

struct Figure
{
    double megabytesPerSecond = 0; // per second of this thread's CPU time
    qint64 passes = 0;
    double seconds = 0; // CPU time
    double wallSeconds = 0;
};

// Runs `pass` (which handles `bytesPerPass` bytes) until it has had kMinimumNs of CPU time. The
// figure is per CPU second, so other processes on the machine change it less than a wall-clock
// figure (on an idle machine the two agree: see seconds and wall_seconds).
Figure time(qint64 bytesPerPass, const std::function<void()> &pass)
{
    pass(); // warm caches and allocator
    Figure figure;
    QElapsedTimer clock;
    clock.start();
    const double cpuStartMs = bench::threadCpuMs();
    do {
        pass();
        ++figure.passes;
    } while ((bench::threadCpuMs() - cpuStartMs) * 1e6 < kMinimumNs);
    figure.seconds = (bench::threadCpuMs() - cpuStartMs) / 1e3;
    figure.wallSeconds = double(clock.nsecsElapsed()) / 1e9;
    figure.megabytesPerSecond =
        double(bytesPerPass) * double(figure.passes) / figure.seconds / kMegabyte;
    return figure;
}

QJsonObject figureJson(const Figure &figure, bool countsMatch)
{
    return {{QStringLiteral("mb_per_s"), figure.megabytesPerSecond},
            {QStringLiteral("passes"), figure.passes},
            {QStringLiteral("cpu_seconds"), figure.seconds},
            {QStringLiteral("wall_seconds"), figure.wallSeconds},
            {QStringLiteral("counts_match"), countsMatch}};
}

// The framer as RequestEngine and the simulator drive it: append what the port delivered, then
// take every item out.
QJsonObject benchFramer(const seriallink::FrameFormat &format, const Traffic &traffic,
                        bool *allMatch)
{
    QJsonObject result;
    double slowest = -1;
    for (const int size : kChunkSizes) {
        const QVector<QByteArray> chunks = chunked(traffic.stream, size);
        qint64 framesOut = 0;
        qint64 frameBytesOut = 0;
        qint64 accepted = 0;
        qint64 discarded = 0;
        qint64 passes = 0;
        const Figure figure = time(traffic.stream.size(), [&] {
            seriallink::StreamFramer framer(format);
            for (const QByteArray &chunk : chunks) {
                framer.append(chunk);
                while (auto item = framer.next()) {
                    if (item->kind == seriallink::StreamItem::Kind::Frame) {
                        ++framesOut;
                        frameBytesOut += item->bytes.size();
                    }
                }
            }
            accepted += framer.framesAccepted();
            discarded += framer.bytesDiscarded();
            ++passes;
        });
        const qint64 frameBytes = traffic.stream.size() - traffic.noiseBytes;
        const bool match = framesOut == accepted && accepted == passes * traffic.frames.size()
            && discarded == passes * traffic.noiseBytes && frameBytesOut == passes * frameBytes;
        *allMatch = *allMatch && match;
        result.insert(QStringLiteral("chunk_%1").arg(size), figureJson(figure, match));
        if (slowest < 0 || figure.megabytesPerSecond < slowest)
            slowest = figure.megabytesPerSecond;
    }
    result.insert(QStringLiteral("min_mb_per_s"), slowest);
    result.insert(QStringLiteral("stream_bytes"), traffic.stream.size());
    result.insert(QStringLiteral("frames_per_pass"), traffic.frames.size());
    result.insert(QStringLiteral("noise_bytes_per_pass"), traffic.noiseBytes);
    return result;
}

qint64 totalSize(const QVector<QByteArray> &frames)
{
    qint64 bytes = 0;
    for (const QByteArray &frame : frames)
        bytes += frame.size();
    return bytes;
}

// Decodes every frame of the traffic each pass. `decode` returns a sum of what it read from one
// frame (nothing when the frame did not decode); the totals must match `expectedPerFrame`.
QJsonObject benchDecoder(const Traffic &traffic,
                         const std::function<std::optional<qint64>(const QByteArray &)> &decode,
                         const std::function<qint64(const QByteArray &)> &expectedPerFrame,
                         bool *allMatch)
{
    qint64 expected = 0;
    for (const QByteArray &frame : traffic.frames)
        expected += expectedPerFrame(frame);
    qint64 decoded = 0;
    qint64 read = 0;
    qint64 passes = 0;
    const Figure figure = time(totalSize(traffic.frames), [&] {
        for (const QByteArray &frame : traffic.frames) {
            if (const auto value = decode(frame)) {
                ++decoded;
                read += *value;
            }
        }
        ++passes;
    });
    const bool match = decoded == passes * traffic.frames.size() && read == passes * expected;
    *allMatch = *allMatch && match;
    return figureJson(figure, match);
}

std::optional<qint64> feetechParameterBytes(const QByteArray &frame)
{
    if (const auto packet = feetech::decodePacket(frame))
        return packet->parameters.size();
    return std::nullopt;
}

// PTK requests carry their words after the command byte, replies right after the length byte.
std::optional<qint64> ptkWordSum(const QByteArray &frame)
{
    if (frame.size() == ptk::kRequestSize) {
        if (const auto request = ptk::decodeRequest(frame))
            return request->word0 + request->word1;
    } else if (const auto reply = ptk::decodeReply(frame)) {
        return reply->word0 + reply->word1;
    }
    return std::nullopt;
}

qint64 ptkWordsOnTheWire(const QByteArray &frame)
{
    const int first = frame.size() == ptk::kRequestSize ? 5 : 4;
    return ptk::wordAt(frame, first) + ptk::wordAt(frame, first + 2);
}

// The packet log: RequestEngine describes every frame a session sends and hears, a reply next to
// its request, on the session's thread (telemetry: hundreds of frames a second).
QJsonObject
benchPacketLog(const std::function<QString(const QByteArray &, const QByteArray &)> &describe,
               const QVector<Exchange> &exchanges, bool *allMatch)
{
    qint64 bytes = 0;
    qint64 frames = 0;
    for (const Exchange &exchange : exchanges) {
        bytes += exchange.request.size() + totalSize(exchange.replies);
        frames += 1 + exchange.replies.size();
    }
    qint64 described = 0;
    qint64 passes = 0;
    const Figure figure = time(bytes, [&] {
        for (const Exchange &exchange : exchanges) {
            described += !describe(exchange.request, exchange.request).isEmpty();
            for (const QByteArray &reply : exchange.replies)
                described += !describe(reply, exchange.request).isEmpty();
        }
        ++passes;
    });
    const bool match = described == passes * frames;
    *allMatch = *allMatch && match;
    QJsonObject result = figureJson(figure, match);
    result.insert(QStringLiteral("us_per_frame"),
                  figure.seconds * 1e6 / double(figure.passes * frames));
    return result;
}

// servoctl decode: the stream split and every frame explained, as the hex line and its summary
// in words or as the JSON object --json prints.
QJsonObject benchDescribe(cli::Protocol protocol, const Traffic &traffic, bool *allMatch)
{
    // servoctl decode reads its bytes from the command line: a capture of a few hundred frames.
    const QByteArray capture = traffic.stream.left(4096);
    const auto reference = cli::decodeStream(protocol, capture);
    QJsonObject result;
    for (const bool json : {false, true}) {
        qint64 frames = 0;
        qint64 characters = 0;
        qint64 passes = 0;
        const Figure figure = time(capture.size(), [&] {
            const auto decoded = cli::decodeStream(protocol, capture,
                                                   json ? seriallink::Detail::SummaryAndFields
                                                        : seriallink::Detail::Summary);
            for (const seriallink::DecodedFrame &frame : decoded) {
                ++frames;
                characters += json ? cli::toJson(frame).size()
                                   : util::toHex(frame.bytes).size() + frame.summary.size();
            }
            ++passes;
        });
        const bool match = frames == passes * reference.size() && characters > 0;
        *allMatch = *allMatch && match;
        result.insert(json ? QStringLiteral("json") : QStringLiteral("words"),
                      figureJson(figure, match));
    }
    result.insert(QStringLiteral("capture_bytes"), capture.size());
    result.insert(QStringLiteral("frames_per_capture"), int(reference.size()));
    return result;
}

} // namespace

// Adds `name`: the lowest mb_per_s among the group's figures at `paths` ("ptk/words"), the one
// a target is held to.
QJsonObject withSlowest(QJsonObject group, const QString &name, const QStringList &paths)
{
    double slowest = -1;
    for (const QString &path : paths) {
        QJsonValue value = group;
        for (const QString &key : path.split(u'/'))
            value = value.toObject().value(key);
        const double figure = value.toObject().value(QStringLiteral("mb_per_s")).toDouble();
        if (slowest < 0 || figure < slowest)
            slowest = figure;
    }
    group.insert(name, slowest);
    return group;
}

// With no argument every group runs; naming groups (framers, packet_decoders, frame_decoder,
// packet_log)
// runs only those, e.g. to profile one of them.
int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    const QStringList groups = QCoreApplication::arguments().mid(1);
    const auto wanted = [&groups](const QString &group) {
        return groups.isEmpty() || groups.contains(group);
    };
    const Traffic ptkTraffic = makeTraffic(ptkExchanges(), QByteArray(1, char(ptk::kHeader0)));
    const Traffic feetechTraffic = makeTraffic(feetechExchanges(), QByteArray(1, char(0xFF)));

    bool allMatch = true;
    QJsonObject report {
        {QStringLiteral("unit"),
         QStringLiteral("MB/s: 10^6 bytes of traffic per second of CPU time")},
        {QStringLiteral("chunk_sizes"),
         QJsonArray {kChunkSizes[0], kChunkSizes[1], kChunkSizes[2]}},
    };
    if (wanted(QStringLiteral("framers")))
        report.insert(
            QStringLiteral("framers"),
            QJsonObject {
                {QStringLiteral("ptk"), benchFramer(ptk::FrameFormat(), ptkTraffic, &allMatch)},
                {QStringLiteral("feetech"),
                 benchFramer(feetech::FrameFormat(), feetechTraffic, &allMatch)},
            });
    if (wanted(QStringLiteral("packet_decoders")))
        report.insert(
            QStringLiteral("packet_decoders"),
            withSlowest(
                QJsonObject {
                    {QStringLiteral("feetech_decode_packet"),
                     benchDecoder(
                         feetechTraffic, feetechParameterBytes,
                         [](const QByteArray &frame) {
                             return frame.size() - feetech::kMinimumPacketSize;
                         },
                         &allMatch)},
                    {QStringLiteral("ptk_decode_frame"),
                     benchDecoder(ptkTraffic, ptkWordSum, ptkWordsOnTheWire, &allMatch)},
                },
                QStringLiteral("min_mb_per_s"),
                {QStringLiteral("feetech_decode_packet"), QStringLiteral("ptk_decode_frame")}));
    if (wanted(QStringLiteral("packet_log")))
        report.insert(QStringLiteral("packet_log"),
                      QJsonObject {
                          {QStringLiteral("ptk"),
                           benchPacketLog(ptk::describeFrame, ptkExchanges(), &allMatch)},
                          {QStringLiteral("feetech"),
                           benchPacketLog(feetech::describeFrame, feetechExchanges(), &allMatch)},
                      });
    if (wanted(QStringLiteral("frame_decoder")))
        report.insert(
            QStringLiteral("frame_decoder"),
            withSlowest(withSlowest(
                            QJsonObject {
                                {QStringLiteral("ptk"),
                                 benchDescribe(cli::Protocol::Ptk, ptkTraffic, &allMatch)},
                                {QStringLiteral("feetech"),
                                 benchDescribe(cli::Protocol::Feetech, feetechTraffic, &allMatch)},
                            },
                            QStringLiteral("words_min_mb_per_s"),
                            {QStringLiteral("ptk/words"), QStringLiteral("feetech/words")}),
                        QStringLiteral("json_min_mb_per_s"),
                        {QStringLiteral("ptk/json"), QStringLiteral("feetech/json")}));
    report.insert(QStringLiteral("counts_match"), allMatch);
    std::printf("%s", QJsonDocument(report).toJson(QJsonDocument::Indented).constData());
    if (!allMatch) {
        std::fprintf(stderr, "bench_codecs: a codec's counts do not match the traffic fed in\n");
        return 1;
    }
    return 0;
}
