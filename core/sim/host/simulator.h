// The simulator: a virtual PTK servo or Feetech bus behind a pseudo-terminal (or a port inside
// this program), with wire-rate pacing, optional echo, fault injection and a frame log.
#pragma once

#include "deviceport.h"
#include "faultinjector.h"
#include "simlog.h"
#include "simoptions.h"
#include "usbadapter.h"
#include "virtualdevice.h"
#include "virtualfeetechbus.h"

#include <QElapsedTimer>
#include <QObject>
#include <QThread>
#include <QTimer>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace sim {

class VirtualPtkServo;

class Simulator : public QObject
{
    Q_OBJECT

public:
    // Checks the options that need the device (models, IDs, bauds, values, state file).
    static std::unique_ptr<Simulator> create(const SimulatorOptions &options, QString *error);
    ~Simulator() override;

    // Opens the port (the pty and its link, or the in-process port); call in the thread the
    // simulator lives in.
    bool start(QString *error);
    void stop();

    // The pty's link, or the name the in-process port is offered under.
    QString linkPath() const { return m_port ? m_port->portName() : QString(); }
    qint64 nowUs() const { return m_clock.nsecsElapsed() / 1000; }

    VirtualDevice &device() { return *m_device; }
    VirtualPtkServo *ptkServo(); // null on a Feetech bus
    VirtualFeetechBus *feetechBus(); // null for PTK
    void powerCycle();
    // Changes the faults from now on (none: a clean link), with a new seed.
    void setFaults(const FaultSettings &faults, quint32 seed);
    // Brings the devices (and the hand) to the present moment; the timer does it every 10 ms.
    void advanceNow();

signals:
    // What the hand did on its own: a sweep finished, or a joint's torque came on and resisted.
    void handNote(const QString &note);

private:
    Simulator(const SimulatorOptions &options, std::unique_ptr<VirtualDevice> device);

    struct Outgoing
    {
        qint64 dueUs = 0;
        QByteArray bytes;
        const char *direction = nullptr; // set on the last chunk of a frame: log it then
        QByteArray frame;
        QString note;
    };

    void onReceived(const QByteArray &bytes);
    void respond(const QVector<Response> &responses, qint32 hostBaud, qint64 requestEndUs);
    void schedule(qint64 startUs, const QByteArray &frame, double byteUs, const char *direction,
                  const QString &note);
    void queue(Outgoing chunk);
    void sendDue();

    SimulatorOptions m_options;
    std::unique_ptr<VirtualDevice> m_device;
    seriallink::DevicePort *m_port = nullptr; // made by start()
    SimLog m_log;
    std::optional<FaultInjector> m_faults;
    std::optional<UsbAdapter> m_adapter;
    std::unique_ptr<seriallink::StreamFramer> m_framer;
    QElapsedTimer m_clock;
    QTimer *m_sendTimer = nullptr;
    QTimer *m_tickTimer = nullptr;
    std::deque<Outgoing> m_outgoing;
    qint64 m_inputEndUs = 0; // when the host's last byte has crossed the wire
    qint64 m_busFreeUs = 0; // when the last scheduled reply has crossed the wire
};

} // namespace sim
