// Measures request/reply round trips through servosim's pty against the wire-time lower bound.
#include "eventloops.h"
#include "feetechpacket.h"
#include "ptkframe.h"
#include "simulatorthread.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QSerialPort>
#include <QTemporaryDir>
#include <QTextStream>

#include <algorithm>
#include <cstdio>

namespace {

constexpr int kRounds = 400;

// Wire time of `bytes` bytes at `baud` (8N1: ten bit times a byte), in microseconds.
double wireUs(int bytes, qint32 baud)
{
    return bytes * 10e6 / baud;
}

QJsonObject measure(const QString &link, qint32 baud, const QByteArray &request, int replySize,
                    int wireBytes)
{
    QSerialPort port(link);
    if (!port.open(QIODevice::ReadWrite) || !port.setBaudRate(baud))
        return {{QStringLiteral("error"), port.errorString()}};
    QVector<double> samples;
    QElapsedTimer clock;
    for (int round = 0; round < kRounds; ++round) {
        QByteArray reply;
        clock.start();
        port.write(request);
        while (reply.size() < replySize && port.waitForReadyRead(1000))
            reply += port.readAll();
        if (reply.size() < replySize)
            return {{QStringLiteral("error"), QStringLiteral("reply missing")}};
        samples.append(double(clock.nsecsElapsed()) / 1000.0);
    }
    std::sort(samples.begin(), samples.end());
    return {{QStringLiteral("rounds"), kRounds},
            {QStringLiteral("median_us"), samples.at(samples.size() / 2)},
            {QStringLiteral("p99_us"), samples.at(samples.size() * 99 / 100)},
            {QStringLiteral("wire_us"), wireUs(wireBytes, baud)}};
}

} // namespace

int main(int argc, char *argv[])
{
    util::preferQtEventLoops(util::QtEventLoops::WorkerThreads); // as servobench does
    QCoreApplication app(argc, argv);
    QTemporaryDir dir;
    QJsonObject result;

    sim::SimulatorOptions ptk;
    ptk.kind = sim::SimulatorOptions::Kind::Ptk;
    ptk.linkPath = dir.filePath(QStringLiteral("ptk"));
    sim::SimulatorThread ptkSimulator;
    QString error;
    if (!ptkSimulator.start(ptk, &error)) {
        std::fprintf(stderr, "bench_simulator: %s\n", qPrintable(error));
        return 1;
    }
    result.insert(QStringLiteral("ptk_query_115200"),
                  measure(ptkSimulator.linkPath(), 115200, ptk::encodeQuery(0x38), ptk::kReplySize,
                          ptk::kRequestSize + ptk::kReplySize));

    sim::SimulatorOptions bus;
    bus.kind = sim::SimulatorOptions::Kind::Feetech;
    bus.linkPath = dir.filePath(QStringLiteral("bus"));
    bus.servos = {{1, QStringLiteral("STS3215"), 1000000}};
    sim::SimulatorThread busSimulator;
    if (!busSimulator.start(bus, &error)) {
        std::fprintf(stderr, "bench_simulator: %s\n", qPrintable(error));
        return 1;
    }
    result.insert(QStringLiteral("feetech_ping_1M"),
                  measure(busSimulator.linkPath(), 1000000, feetech::ping(1), 6, 12));
    result.insert(QStringLiteral("feetech_read_feedback_15B_1M"),
                  measure(busSimulator.linkPath(), 1000000, feetech::read(1, 56, 15), 21, 8 + 21));

    QTextStream(stdout) << QJsonDocument(result).toJson(QJsonDocument::Indented);
    return 0;
}
