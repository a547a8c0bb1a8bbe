// Unit tests of the simulated USB adapters: when each profile hands the wire's bytes to the
// program (FTDI's latency timer, packets, CH34x and CP210x frames), and servosim's --adapter.
#include "simoptions.h"
#include "usbadapter.h"

#include <QtTest>

using sim::UsbAdapter;

namespace {

constexpr qint64 kByteUs1M = 10; // one byte at 1 Mbps, 8N1

// `count` bytes on the wire one after the other, the first complete at `firstUs`.
void hear(UsbAdapter &adapter, qint64 firstUs, int count, char byte = 'x')
{
    for (int i = 0; i < count; ++i)
        adapter.heard(firstUs + i * kByteUs1M, byte);
}

sim::AdapterProfile profile(const char *name)
{
    const auto found = sim::adapterProfile(QString::fromLatin1(name));
    Q_ASSERT(found);
    return *found;
}

} // namespace

class TestUsbAdapter : public QObject
{
    Q_OBJECT

private slots:
    void ftdiHoldsAShortAnswerUntilItsLatencyTimerRunsOut()
    {
        UsbAdapter adapter(profile("ftdi"), 1);
        hear(adapter, 2000, 10);
        const qint64 due = adapter.nextDeliveryUs();
        QVERIFY(due >= 16000);
        QVERIFY(due <= 16000 + profile("ftdi").jitterUs);
        QVERIFY(adapter.takeDelivery(due - 1).isEmpty());
        QCOMPARE(adapter.takeDelivery(due), QByteArray(10, 'x'));
        QCOMPARE(adapter.nextDeliveryUs(), UsbAdapter::kNever);
        // The timer started again with that packet: the next answer waits for its next run.
        hear(adapter, 17000, 6, 'y');
        QVERIFY(adapter.nextDeliveryUs() >= 32000);
    }

    void ftdiSendsAFullPacketAtOnceAndTheRestWithTheTimer()
    {
        UsbAdapter adapter(profile("ftdi-1ms"), 1);
        UsbAdapter slow(profile("ftdi"), 1);
        for (UsbAdapter *each : {&adapter, &slow})
            hear(*each, 40000, 100);
        // The 62nd byte is on the wire at 40 610 µs: that packet goes with the next USB frame.
        const qint64 first = slow.nextDeliveryUs();
        QVERIFY(first >= 41000 && first <= 41000 + profile("ftdi").jitterUs);
        QCOMPARE(slow.takeDelivery(first).size(), 62);
        QVERIFY(slow.nextDeliveryUs() >= 41000 + 16000);
        QCOMPARE(slow.takeDelivery(slow.nextDeliveryUs()).size(), 38);
        // At 1 ms, whatever the wire brought goes every millisecond: the full packet at 41 ms
        // starts the timer again, and the rest goes with its next run.
        int delivered = 0;
        qint64 last = 0;
        while (adapter.nextDeliveryUs() != UsbAdapter::kNever) {
            last = adapter.nextDeliveryUs();
            const int size = int(adapter.takeDelivery(last).size());
            QVERIFY(size >= 1 && size <= 62);
            delivered += size;
        }
        QCOMPARE(delivered, 100);
        QVERIFY(last <= 42000 + profile("ftdi-1ms").jitterUs);
    }

    void ch340SendsOnceTheLineIsQuietInItsOwnPackets()
    {
        const sim::AdapterProfile ch340 = profile("ch340");
        UsbAdapter adapter(ch340, 7);
        hear(adapter, 100, 20); // quiet from 290 µs on
        const qint64 due = adapter.nextDeliveryUs();
        QVERIFY(due >= 1000);
        QVERIFY(due <= 1000 + ch340.jitterUs + ch340.stallFrames * ch340.frameUs);
        QCOMPARE(adapter.takeDelivery(due).size(), 20);
        // More than a packet's worth: 32 bytes at a time.
        hear(adapter, 5000, 50);
        QCOMPARE(adapter.takeDelivery(adapter.nextDeliveryUs()).size(), ch340.packetBytes);
        QCOMPARE(adapter.takeDelivery(adapter.nextDeliveryUs()).size(), 50 - ch340.packetBytes);
    }

    void aRequestReachesTheWireWithTheNextUsbFrame()
    {
        const UsbAdapter adapter(profile("cp2102"), 1);
        QCOMPARE(adapter.requestOnWireUs(1500), 2000);
        QCOMPARE(adapter.requestOnWireUs(2000), 2000);
    }

    void theSameSeedGivesTheSameDeliveries()
    {
        const auto deliveries = [](quint32 seed) {
            UsbAdapter adapter(profile("ch340"), seed);
            QVector<qint64> times;
            for (int answer = 0; answer < 50; ++answer) {
                hear(adapter, answer * 10000, 30);
                const qint64 due = adapter.nextDeliveryUs();
                times.append(due);
                adapter.takeDelivery(due);
            }
            return times;
        };
        QCOMPARE(deliveries(3), deliveries(3));
        QVERIFY(deliveries(3) != deliveries(4));
    }

    void servosimTakesAnAdapterProfile()
    {
        QString error;
        const QStringList base {QStringLiteral("ptk"), QStringLiteral("--link"),
                                QStringLiteral("/tmp/unused"), QStringLiteral("--adapter")};
        const auto ftdi =
            sim::parseSimulatorArguments(base + QStringList {QStringLiteral("ftdi")}, &error);
        QVERIFY(ftdi && ftdi->adapter);
        QCOMPARE(ftdi->adapter->latencyTimerUs, 16000);
        QVERIFY(!ftdi->instant);
        const auto ideal =
            sim::parseSimulatorArguments(base + QStringList {QStringLiteral("ideal")}, &error);
        QVERIFY(ideal && !ideal->adapter && !ideal->instant);
        // A device that answers the moment a frame is complete: no adapter, no wire time.
        const auto instant =
            sim::parseSimulatorArguments(base + QStringList {QStringLiteral("instant")}, &error);
        QVERIFY(instant && !instant->adapter && instant->instant);
        QVERIFY(
            !sim::parseSimulatorArguments(base + QStringList {QStringLiteral("pl2303")}, &error));
        QVERIFY2(error.contains(QStringLiteral("unknown adapter \"pl2303\"")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("ftdi-1ms")), qPrintable(error));
        QVERIFY2(error.contains(QStringLiteral("instant")), qPrintable(error));
        QVERIFY(!sim::parseSimulatorArguments(base, &error));
        QCOMPARE(sim::adapterProfileNames().first(), QStringLiteral("ideal"));
        for (const QString &name : sim::adapterProfileNames().mid(1))
            QVERIFY(sim::adapterProfile(name));
    }
};

QTEST_GUILESS_MAIN(TestUsbAdapter)
#include "tst_usbadapter.moc"
