// The simulator: a virtual PTK servo or Feetech bus behind a pseudo-terminal, with wire-rate
// pacing, optional echo, fault injection and a frame log.
#pragma once

#include "faults.h"
#include "hand.h"
#include "pseudoterminal.h"
#include "robottemplate.h"
#include "simlog.h"
#include "usbadapter.h"
#include "virtualdevice.h"
#include "virtualfeetechbus.h"

#include <QElapsedTimer>
#include <QObject>
#include <QStringList>
#include <QThread>
#include <QTimer>

#include <deque>
#include <functional>
#include <memory>
#include <optional>

namespace sim {

class VirtualPtkServo;

using FeetechServoSpec = VirtualFeetechBus::ServoSpec;

// A scripted sweep of the hand (sim/hand.h), from the command line or standard input.
struct HandSweep
{
    quint8 id = 1;
    int from = 0;
    int to = 0;
    double seconds = 1.0;
    int cycles = 0; // 0: until released
    Hand::Way way = Hand::Way::Direct;
};

// ID:MODEL[@BAUD], as --servo and the plug command take it; `source` names it in errors.
std::optional<FeetechServoSpec> parseServoSpec(const QString &text, const QString &source,
                                               QString *error);
// FIELDS are ID FROM TO SECONDS [CYCLES] [up|down], already split; `source` names them in errors.
std::optional<HandSweep> parseHandSweep(const QStringList &fields, const QString &source,
                                        QString *error);
// The built-in robot templates servosim plays: so100, so101 (follower arms), so100-leader,
// so101-leader. Nothing and *error for another name.
std::optional<feetech::RobotTemplate> simulatedRobot(const QString &name, QString *error);
// The robot's joints as servos on the bus, at the template's rate.
QVector<FeetechServoSpec> robotServos(const feetech::RobotTemplate &robot);

struct SimulatorOptions
{
    enum class Kind { Ptk, Feetech };
    Kind kind = Kind::Ptk;
    QString linkPath;
    bool echo = false; // answer every host byte back first, like a single-wire adapter
    FaultSettings faults;
    quint32 seed = 1;
    QString logPath;
    qint64 replyDelayUs = 0; // added to every reply's turnaround
    // --adapter: replies reach the program as through this USB adapter; none: as a pty gives
    // them (ideal).
    std::optional<AdapterProfile> adapter;
    // --adapter instant: a device that answers the moment a frame is complete, in no wire time
    // and with no return delay (a virtual port, an emulator, a USB CDC device).
    bool instant = false;
    QString ptkValues; // "gain=20,..." starting values of the PTK servo
    QVector<FeetechServoSpec> servos;
    QString statePath; // Feetech: keeps EEPROM across runs
    bool allowSharedIds = false; // two --servo at one ID and rate, replies colliding
    // --robot: its joints are the first servos, set up with its settings, horns at rest.
    std::optional<feetech::RobotTemplate> robot;
    QVector<HandSweep> sweeps; // --hand, started with the bus
    QStringList commands; // --command: standard-input commands run before "ready"
};

// Parses servosim's arguments (program name excluded); nothing and *error on a bad one.
std::optional<SimulatorOptions> parseSimulatorArguments(const QStringList &arguments,
                                                        QString *error);
QString simulatorUsage();

class Simulator : public QObject
{
    Q_OBJECT

public:
    // Checks the options that need the device (models, IDs, bauds, values, state file).
    static std::unique_ptr<Simulator> create(const SimulatorOptions &options, QString *error);
    ~Simulator() override;

    // Opens the pty and makes the link; call in the thread the simulator lives in.
    bool start(QString *error);
    void stop();

    QString linkPath() const { return m_pty->linkPath(); }
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
    PseudoTerminal *m_pty = nullptr;
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

// Runs a simulator on its own thread (tests and the GUI's demo mode).
class SimulatorThread
{
public:
    SimulatorThread() = default;
    ~SimulatorThread();
    SimulatorThread(const SimulatorThread &) = delete;
    SimulatorThread &operator=(const SimulatorThread &) = delete;

    bool start(const SimulatorOptions &options, QString *error);
    void stop();
    bool isRunning() const { return m_simulator != nullptr; }
    QString linkPath() const { return m_linkPath; }

    // Runs `work` in the simulator's thread and waits for it: the only safe way to look at or
    // change the simulated devices while they run.
    void call(const std::function<void(Simulator &)> &work);

private:
    QThread m_thread;
    std::unique_ptr<Simulator> m_simulator;
    QString m_linkPath;
};

} // namespace sim
