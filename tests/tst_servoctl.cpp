// Tests servoctl's offline commands (decode, packet) in-process: output and exit codes.
#include "hex.h"
#include "lineoutlet.h"
#include "servoctlrun.h"
#include "specvectors.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include <thread>

#include <fcntl.h>
#include <unistd.h>

namespace {

using Result = testsupport::ServoctlResult;
constexpr auto run = testsupport::runServoctl;

QString hexLine(const char *spec)
{
    return util::toHex(specvectors::bytes(spec));
}

} // namespace

class TestServoctl : public QObject
{
    Q_OBJECT

private slots:
    // servoctl's stdout and stderr: a stream never waits for a reader who stopped reading.
    void anOutletThatMayDropNeverWaitsAndSaysWhatItDroppedOnceReadingResumes()
    {
        int ends[2];
        QCOMPARE(::pipe(ends), 0);
        QCOMPARE(::fcntl(ends[0], F_SETFL, O_NONBLOCK), 0);
        const auto closeRead = qScopeGuard([&] { ::close(ends[0]); });
        const auto readAll = [&] {
            QByteArray all;
            char buffer[65536];
            for (ssize_t got; (got = ::read(ends[0], buffer, sizeof buffer)) > 0;)
                all.append(buffer, got);
            return all;
        };
        {
            util::LineOutlet outlet(ends[1], 4096);
            outlet.setWhenFull(util::LineOutlet::WhenFull::Drop);
            outlet.setDroppedLine([](qint64 count) -> QByteArray {
                return "{\"dropped\":" + QByteArray::number(count) + "}\n";
            });
            QTextStream out(&outlet);
            // Nobody reads: far more than the pipe and the queue hold goes without waiting.
            const QByteArray line(99, 'x');
            for (int i = 0; i < 10000; ++i)
                out << line << '\n' << Qt::flush;
            QVERIFY(outlet.droppedLines() > 9000);
            const qint64 dropped = outlet.droppedLines();
            QByteArray read;
            QVERIFY(QTest::qWaitFor(
                [&] {
                    read += readAll();
                    return outlet.drain(std::chrono::milliseconds(0));
                },
                5000));
            read += readAll();
            out << "after\n" << Qt::flush;
            QVERIFY(outlet.drain());
            read += readAll();
            // Every line lost is counted where reading resumed (more than once when the writer
            // caught up for a moment meanwhile); every other line arrived.
            const QList<QByteArray> lines = read.trimmed().split('\n');
            qint64 counted = 0;
            int plain = 0;
            for (const QByteArray &line : lines) {
                if (line.startsWith("{\"dropped\":"))
                    counted += line.mid(11, line.size() - 12).toLongLong();
                else if (line == QByteArray(99, 'x'))
                    ++plain;
            }
            QCOMPARE(counted, dropped);
            QCOMPARE(plain, 10000 - dropped);
            QVERIFY(lines.at(lines.size() - 2).startsWith("{\"dropped\":"));
            QCOMPARE(lines.last(), QByteArray("after"));
        }
        ::close(ends[1]);
    }

    void anOutletThatWaitsLosesNothing()
    {
        int ends[2];
        QCOMPARE(::pipe(ends), 0);
        QByteArray read;
        std::thread reader([&] {
            char buffer[4096];
            for (ssize_t got; (got = ::read(ends[0], buffer, sizeof buffer)) > 0;)
                read.append(buffer, got);
        });
        {
            util::LineOutlet outlet(ends[1], 4096);
            QTextStream out(&outlet);
            for (int i = 0; i < 20000; ++i)
                out << i << '\n';
        } // the outlet writes everything before it goes
        ::close(ends[1]);
        reader.join();
        ::close(ends[0]);
        const QList<QByteArray> lines = read.trimmed().split('\n');
        QCOMPARE(lines.size(), 20000);
        QCOMPARE(lines.last(), QByteArray("19999"));
    }

    void ptkQueriesReproduceTheSpecFrames()
    {
        for (const auto &exchange : specvectors::kPtkExchanges) {
            const Result byName = run({QStringLiteral("packet"), QStringLiteral("ptk"),
                                       QStringLiteral("query"), QLatin1String(exchange.name)});
            QCOMPARE(byName.exitCode, 0);
            QCOMPARE(byName.out.trimmed(), hexLine(exchange.query));
            const Result byNumber =
                run({QStringLiteral("packet"), QStringLiteral("ptk"), QStringLiteral("query"),
                     QString::number(exchange.command)});
            QCOMPARE(byNumber.out.trimmed(), hexLine(exchange.query));
        }
    }

    void ptkWriteOfEveryParameterPrintsTheTwelveFramesInOrder()
    {
        const Result result = run(
            QStringList {QStringLiteral("packet"), QStringLiteral("ptk"), QStringLiteral("write")}
            + QStringList {QStringLiteral("gain=29"), QStringLiteral("damping=12"),
                           QStringLiteral("deadband=15"), QStringLiteral("neutral=4096"),
                           QStringLiteral("min_angle=65"), QStringLiteral("max_angle=65"),
                           QStringLiteral("min_pulse_us=500"), QStringLiteral("max_pulse_us=2500"),
                           QStringLiteral("max_power=1200"), QStringLiteral("overload_power=800"),
                           QStringLiteral("overload_time_ms=2000"), QStringLiteral("inversion=on"),
                           QStringLiteral("soft_start=1")});
        QCOMPARE(result.exitCode, 0);
        QStringList expected;
        for (const char *frame : specvectors::kPtkWrites)
            expected.append(hexLine(frame));
        QCOMPARE(result.out.split(u'\n', Qt::SkipEmptyParts), expected);
    }

    void ptkWriteOfOneParameterPrintsItsFrame()
    {
        const Result result = run({QStringLiteral("packet"), QStringLiteral("ptk"),
                                   QStringLiteral("write"), QStringLiteral("gain=29")});
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(result.out.trimmed(), hexLine(specvectors::kPtkWrites[0]));
    }

    void feetechPacketsReproduceTheSeedFrames_data()
    {
        QTest::addColumn<QStringList>("arguments");
        QTest::addColumn<QString>("frame");
        const auto row = [](const char *name, const QString &args, const char *frame) {
            QTest::newRow(name) << args.split(u' ') << util::toHex(specvectors::bytes(frame));
        };
        row("ping", QStringLiteral("--id 1"), "FFFF010201FB");
        row("read", QStringLiteral("--id 1 --addr 0x38 --len 2"), "FFFF0104023802BE");
        row("write", QStringLiteral("--id 254 --addr 5 --data 01"), "FFFFFE04030501F4");
        row("write", QStringLiteral("--id 1 --addr 0x2A --data 00080000E803"),
            "FFFF0109032A00080000E803D5");
        row("reg-write", QStringLiteral("--id 1 --addr 42 --data 00,08,00,00,E8,03"),
            "FFFF0109042A00080000E803D4");
        row("action", QString(), "FFFFFE0205FA");
        row("sync-write", QStringLiteral("--addr 0x2A --ids 1-4 --data 00080000E803"),
            "FFFFFE20832A0601000800 00E803020008 0000E803030008 0000E803040008 0000E80358");
        row("recovery", QStringLiteral("--id 0"), "FFFF00020 6F7");
        row("recovery", QStringLiteral("--id 1"), "FFFF010206F6");
        row("calibrate", QStringLiteral("--id 1 --data 0004"), "FFFF01040B0004EB");
    }
    void feetechPacketsReproduceTheSeedFrames()
    {
        QFETCH(QStringList, arguments);
        QFETCH(QString, frame);
        const QString instruction = QString::fromLatin1(QTest::currentDataTag());
        QStringList all {QStringLiteral("packet"), QStringLiteral("feetech"), instruction};
        for (const QString &argument : arguments) {
            if (!argument.isEmpty())
                all.append(argument);
        }
        const Result result = run(all);
        QCOMPARE(result.err, QString());
        QCOMPARE(result.exitCode, 0);
        QCOMPARE(result.out.trimmed(), frame);
    }

    void syncWriteTakesOneBlockPerServoWithLen()
    {
        const Result result =
            run({QStringLiteral("packet"), QStringLiteral("feetech"), QStringLiteral("sync-write"),
                 QStringLiteral("--addr"), QStringLiteral("42"), QStringLiteral("--len"),
                 QStringLiteral("2"), QStringLiteral("--ids"), QStringLiteral("1,2"),
                 QStringLiteral("--data"), QStringLiteral("0008 0004")});
        QCOMPARE(result.exitCode, 0);
        QVERIFY(result.out.startsWith(QStringLiteral("FF FF FE 0A 83 2A 02 01 00 08 02 00 04")));
    }

    void malformedInputExitsTwoWithOneLineAndPrintsNothing_data()
    {
        QTest::addColumn<QString>("arguments");
        QTest::newRow("odd hex") << QStringLiteral("decode AF F");
        QTest::newRow("not hex") << QStringLiteral("decode ZZ");
        QTest::newRow("no header") << QStringLiteral("decode 01 02");
        QTest::newRow("bad family") << QStringLiteral("decode --family dxl FF");
        QTest::newRow("unknown command") << QStringLiteral("frobnicate");
        QTest::newRow("unknown option") << QStringLiteral("decode --fast FF FF");
        QTest::newRow("no command") << QString();
        QTest::newRow("unknown instruction") << QStringLiteral("packet feetech jump --id 1");
        QTest::newRow("read broadcast")
            << QStringLiteral("packet feetech read --id 254 --addr 0 --len 1");
        QTest::newRow("id over 254") << QStringLiteral("packet feetech ping --id 300");
        QTest::newRow("id not a number") << QStringLiteral("packet feetech ping --id one");
        QTest::newRow("missing id") << QStringLiteral("packet feetech ping");
        QTest::newRow("missing len") << QStringLiteral("packet feetech read --id 1 --addr 0");
        QTest::newRow("addr too big")
            << QStringLiteral("packet feetech read --id 1 --addr 256 --len 1");
        QTest::newRow("option not taken") << QStringLiteral("packet feetech ping --id 1 --addr 3");
        QTest::newRow("odd data") << QStringLiteral(
            "packet feetech write --id 1 --addr 3 --data 0");
        QTest::newRow("sync ids over 253")
            << QStringLiteral("packet feetech sync-read --addr 56 --len 2 --ids 1,254");
        QTest::newRow("sync data length") << QStringLiteral(
            "packet feetech sync-write --addr 42 --len 2 --ids 1,2 --data 000102");
        QTest::newRow("ptk unknown key") << QStringLiteral("packet ptk write speed=3");
        QTest::newRow("ptk out of range") << QStringLiteral("packet ptk write gain=31");
        QTest::newRow("ptk not a number") << QStringLiteral("packet ptk write gain=high");
        QTest::newRow("ptk half a frame") << QStringLiteral("packet ptk write overload_power=800");
        QTest::newRow("ptk bad query") << QStringLiteral("packet ptk query 300");
        QTest::newRow("unknown protocol") << QStringLiteral("packet dxl ping");
    }
    void malformedInputExitsTwoWithOneLineAndPrintsNothing()
    {
        QFETCH(QString, arguments);
        const Result result = run(arguments.split(u' ', Qt::SkipEmptyParts));
        QCOMPARE(result.exitCode, int(cli::ExitUsage));
        QCOMPARE(result.out, QString());
        QCOMPARE(result.err.count(u'\n'), 1);
        QVERIFY(result.err.startsWith(QStringLiteral("servoctl: ")));
    }

    void decodeJsonIsOneArrayOfFrames()
    {
        QStringList arguments {QStringLiteral("--json"), QStringLiteral("decode")};
        arguments.append(util::toHex(specvectors::ptkConversation(true)).split(u' '));
        const Result result = run(arguments);
        QCOMPARE(result.exitCode, 0);
        QJsonParseError error {};
        const QJsonDocument document = QJsonDocument::fromJson(result.out.toUtf8(), &error);
        QCOMPARE(error.error, QJsonParseError::NoError);
        QVERIFY(document.isArray());
        QCOMPARE(document.array().size(), 16);
        QCOMPARE(document.array().at(1).toObject().value(QStringLiteral("kind")).toString(),
                 QStringLiteral("reply"));
    }

    void decodeTextShowsEveryFrameWithItsChecksumVerdict()
    {
        const Result result = run({QStringLiteral("decode"), QStringLiteral("FF FF 01 02 01 FB"),
                                   QStringLiteral("FF FF 01 02 00 FD")});
        QCOMPARE(result.exitCode, 0);
        QVERIFY(result.out.contains(QStringLiteral("PING ID 1 [checksum ok]")));
        QVERIFY(result.out.contains(QStringLiteral("[BAD CHECKSUM]")));
    }

    void helpPrintsUsageAndSucceeds()
    {
        const Result result = run({QStringLiteral("--help")});
        QCOMPARE(result.exitCode, 0);
        QVERIFY(result.out.contains(QStringLiteral("usage: servoctl")));
    }
};

QTEST_GUILESS_MAIN(TestServoctl)
#include "tst_servoctl.moc"
