// The system's serial ports as ServoBench offers them: USB adapters first, since servos hang on
// one, then the rest (a PC's built-in ttyS0 rarely has anything on it).
#pragma once

#include <QString>
#include <QVector>

#include <optional>

class QSerialPortInfo;

struct SerialPort
{
    QString path; // what is opened: /dev/ttyUSB0, COM3
    QString name; // ttyUSB0
    QString description; // the USB product's own name, empty for a built-in port
    QString manufacturer;
    QString serialNumber;
    std::optional<quint16> vendorId;
    std::optional<quint16> productId;

    static SerialPort from(const QSerialPortInfo &info);
    // A USB vendor and product ID or a description: an adapter someone plugged in.
    bool isUsbAdapter() const;
    QString usbId() const; // "1a86:7523", empty without one
    bool operator==(const SerialPort &other) const;
};

// `ports` with the USB adapters first, each group in the order it came.
QVector<SerialPort> usbAdaptersFirst(QVector<SerialPort> ports);
// The system's ports now, USB adapters first.
QVector<SerialPort> availableSerialPorts();
