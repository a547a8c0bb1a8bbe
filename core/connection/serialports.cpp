// The system's serial ports, USB adapters first.
#include "serialports.h"

#include <QSerialPortInfo>

#include <algorithm>

SerialPort SerialPort::from(const QSerialPortInfo &info)
{
    SerialPort port;
    port.path = info.systemLocation();
    port.name = info.portName();
    port.description = info.description();
    port.manufacturer = info.manufacturer();
    port.serialNumber = info.serialNumber();
    if (info.hasVendorIdentifier())
        port.vendorId = info.vendorIdentifier();
    if (info.hasProductIdentifier())
        port.productId = info.productIdentifier();
    return port;
}

bool SerialPort::isUsbAdapter() const
{
    return (vendorId && productId) || !description.isEmpty();
}

QString SerialPort::usbId() const
{
    if (!vendorId || !productId)
        return {};
    return QStringLiteral("%1:%2")
        .arg(*vendorId, 4, 16, QLatin1Char('0'))
        .arg(*productId, 4, 16, QLatin1Char('0'));
}

bool SerialPort::operator==(const SerialPort &other) const
{
    return path == other.path && name == other.name && description == other.description
        && manufacturer == other.manufacturer && serialNumber == other.serialNumber
        && vendorId == other.vendorId && productId == other.productId;
}

QVector<SerialPort> usbAdaptersFirst(QVector<SerialPort> ports)
{
    std::stable_partition(ports.begin(), ports.end(),
                          [](const SerialPort &port) { return port.isUsbAdapter(); });
    return ports;
}

QVector<SerialPort> availableSerialPorts()
{
    QVector<SerialPort> ports;
    for (const QSerialPortInfo &info : QSerialPortInfo::availablePorts())
        ports.append(SerialPort::from(info));
    return usbAdaptersFirst(std::move(ports));
}
