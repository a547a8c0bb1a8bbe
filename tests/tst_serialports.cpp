// Tests the order in which ServoBench offers the system's serial ports: USB adapters (a vendor
// and product ID, or a description) before built-in ports, each group in its own order.
#include "serialports.h"
#include "serialportwatcher.h"

#include <QTemporaryDir>
#include <QtTest>

namespace {

SerialPort builtIn(const QString &name)
{
    SerialPort port;
    port.name = name;
    port.path = QStringLiteral("/dev/") + name;
    return port;
}

SerialPort usb(const QString &name, quint16 vendor, quint16 product, const QString &description)
{
    SerialPort port = builtIn(name);
    port.vendorId = vendor;
    port.productId = product;
    port.description = description;
    return port;
}

QStringList namesOf(const QVector<SerialPort> &ports)
{
    QStringList names;
    for (const SerialPort &port : ports)
        names.append(port.name);
    return names;
}

} // namespace

class TestSerialPorts : public QObject
{
    Q_OBJECT

private slots:
    void usbAdaptersComeBeforeBuiltInPortsInTheirOwnOrder()
    {
        const QVector<SerialPort> ports {
            builtIn(QStringLiteral("ttyS0")), usb(QStringLiteral("ttyUSB1"), 0x1a86, 0x7523, {}),
            builtIn(QStringLiteral("ttyS1")),
            usb(QStringLiteral("ttyACM0"), 0x2e8a, 0x000a, QStringLiteral("URT-1"))};
        QCOMPARE(namesOf(usbAdaptersFirst(ports)),
                 (QStringList {QStringLiteral("ttyUSB1"), QStringLiteral("ttyACM0"),
                               QStringLiteral("ttyS0"), QStringLiteral("ttyS1")}));
    }

    void aDescriptionAloneMakesAnAdapter()
    {
        SerialPort described = builtIn(QStringLiteral("cu.usbserial"));
        described.description = QStringLiteral("USB Serial");
        QVERIFY(described.isUsbAdapter());
        QVERIFY(!builtIn(QStringLiteral("ttyS0")).isUsbAdapter());
        SerialPort halfAnId = builtIn(QStringLiteral("ttyS2"));
        halfAnId.vendorId = 0x0403;
        QVERIFY(!halfAnId.isUsbAdapter());
    }

    void usbIdIsVendorColonProductInHex()
    {
        QCOMPARE(usb(QStringLiteral("ttyUSB0"), 0x0403, 0x6001, {}).usbId(),
                 QStringLiteral("0403:6001"));
        QCOMPARE(builtIn(QStringLiteral("ttyS0")).usbId(), QString());
    }

    void theSystemsPortsAreListedAdaptersFirst()
    {
        const QVector<SerialPort> ports = availableSerialPorts();
        const auto firstBuiltIn = std::find_if(
            ports.cbegin(), ports.cend(), [](const SerialPort &p) { return !p.isUsbAdapter(); });
        QVERIFY(std::none_of(firstBuiltIn, ports.cend(),
                             [](const SerialPort &p) { return p.isUsbAdapter(); }));
    }

    // Each listing walks sysfs: an idle window lists the ports once, and again only when a
    // device node comes or goes.
    void theWatcherListsThePortsAgainOnlyWhenADeviceComesOrGoes()
    {
        QTemporaryDir devices;
        QVERIFY(devices.isValid());
        SerialPortWatcher watcher(devices.path());
        QCOMPARE(watcher.listings(), 1);
        QCOMPARE(watcher.ports(), availableSerialPorts());
        QTest::qWait(1500); // what the window's two timers listed three times in
        QCOMPARE(watcher.listings(), 1);
        QFile node(devices.filePath(QStringLiteral("ttyUSB7")));
        QVERIFY(node.open(QIODevice::WriteOnly));
        node.close();
        QTRY_COMPARE(watcher.listings(), 2);
        QVERIFY(node.remove());
        QTRY_COMPARE(watcher.listings(), 3);
    }
};

QTEST_GUILESS_MAIN(TestSerialPorts)
#include "tst_serialports.moc"
