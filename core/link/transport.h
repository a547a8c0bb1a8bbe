// The byte pipe the request engine talks through: a port, a shared bus's gate, a fake in tests.
#pragma once

#include <QByteArray>
#include <QObject>
#include <QString>

namespace seriallink {

class Transport : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;

    virtual bool isOpen() const = 0;
    virtual qint32 baudRate() const = 0;
    virtual void write(const QByteArray &bytes) = 0;
    // Takes whatever input is waiting, delivered or not, so that nothing received before a new
    // request can be taken for its answer. Returns the bytes it could still see.
    virtual QByteArray discardInput() = 0;
    // Delivers (through received) input that has arrived but not been announced yet. A timeout
    // asks first: on a busy machine the timer can fire before the read of a reply that is
    // already there.
    virtual void deliverPendingInput() { }

signals:
    void received(const QByteArray &bytes);
    void bytesWritten(qint64 count);
    // The port failed; `lost` when the device itself went away (unplugged, simulator gone).
    void failed(const QString &message, bool lost);
};

} // namespace seriallink
