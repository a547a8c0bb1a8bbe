// Test support for a shared bus: the other program, on a port of its own at the share's path.
#pragma once

#include "feetechpacket.h"
#include "registertable.h"
#include "streamframer.h"

#include <QSerialPort>
#include <QtTest>

namespace testsupport {

// The feedback block of an STS servo: what a program's monitoring loop reads.
inline feetech::Block stsFeedbackBlock()
{
    return feetech::RegisterTable::forFamily(feetech::Family::Sts).feedbackBlock();
}

// A program on a shared bus, asking and waiting as a program's loop does (LeRobot opens the
// path as a serial port at 1 Mbps and reads each servo's model number first).
class ProgramPort
{
public:
    static constexpr int kModelAddress = 3;

    bool open(const QString &path, qint32 baud = 1000000)
    {
        m_port.setPortName(path);
        if (!m_port.open(QIODevice::ReadWrite))
            return false;
        return m_port.setBaudRate(baud);
    }
    void close() { m_port.close(); }

    // Sends `request` and collects `answers` frames; fewer when they did not all come in 5 s.
    QVector<QByteArray> ask(const QByteArray &request, int answers)
    {
        send(request);
        return collect(answers);
    }

    void send(const QByteArray &request)
    {
        m_requests.append(request);
        m_port.write(request);
    }

    // The next `answers` frames the program hears; fewer when they did not all come in 5 s.
    QVector<QByteArray> collect(int answers)
    {
        QVector<QByteArray> frames;
        const bool complete = QTest::qWaitFor(
            [&] {
                m_framer.append(m_port.readAll());
                while (const auto item = m_framer.next()) {
                    if (item->kind == seriallink::StreamItem::Kind::Frame)
                        frames.append(item->bytes);
                }
                return frames.size() >= answers;
            },
            5000);
        if (!complete)
            qWarning("%d of %d answers came within 5 s", int(frames.size()), answers);
        return frames;
    }

    // Its model number, as a program reads it when it connects: whether servo `id` answered.
    bool readModel(quint8 id) { return ask(feetech::read(id, kModelAddress, 2), 1).size() == 1; }

    // Every request it sent, in order.
    const QVector<QByteArray> &requests() const { return m_requests; }

private:
    QSerialPort m_port;
    feetech::FrameFormat m_format; // the framer keeps a reference: declared first
    seriallink::StreamFramer m_framer {m_format};
    QVector<QByteArray> m_requests;
};

} // namespace testsupport
