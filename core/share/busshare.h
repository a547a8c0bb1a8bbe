// ServoBench between another program and the servos: a pseudo-terminal for the program, every
// byte forwarded to the real port and back, and what passes decoded, watched and recorded.
#pragma once

#include "busgate.h"
#include "observedservos.h"
#include "sharealerts.h"
#include "sharedtransaction.h"
#include "sharerecording.h"
#include "telemetry.h"

#include <QHash>
#include <QObject>
#include <QTimer>

#include <memory>

namespace seriallink {
class LinkSession;
class PseudoTerminal;
} // namespace seriallink

namespace share {

class ShareWatch;

struct ShareOptions
{
    QString linkPath; // the path the other program opens (a symlink to the pseudo-terminal)
    QString recordPath; // empty: no recording
    bool watch = false;
};

// Works on an open link (the CLI's, or a GUI session's, in that link's thread): while it
// shares, the link's request engine talks through the gate, so ServoBench's own requests go
// between the program's transactions, never across them. The rate the program sets on its
// side is set on the port before its next bytes go. An adapter that goes away is reported and
// the share goes on when the link has it back; the program closing and opening its side again
// changes nothing.
class BusShare : public QObject
{
    Q_OBJECT

public:
    explicit BusShare(seriallink::LinkSession &link, QObject *parent = nullptr);
    ~BusShare() override;

    // Makes the pseudo-terminal and the link, opens the recording. Empty when sharing began,
    // else why not (nothing was changed then).
    QString start(const ShareOptions &options);
    void stop();
    bool isSharing() const;
    QString linkPath() const;
    // The pseudo-terminal itself, for a message that names both.
    QString terminalPath() const;

    void setWatch(bool enabled);
    bool isWatching() const;

    const ShareCounters &counters() const;
    const ObservedServos &servos() const { return m_servos; }
    int alertCount() const { return m_alerts.raisedCount(); }
    qint64 watchReads() const;
    // One paragraph on what passed: frames and bytes each way, errors, alerts.
    QString summary() const;

signals:
    // A transaction ended (the program's, or the watch's own), its meaning filled in.
    void transactionEnded(const share::SharedTransaction &transaction);
    void alertRaised(const share::ShareAlert &alert);
    // What the transaction's answers reported of each servo's feedback (the quantities it
    // read; the others empty), for plots and readouts.
    void feedbackSeen(const QVector<feetech::FeedbackSample> &samples);
    // Something that happened to the share: a rate the program set, the adapter lost or back.
    void noted(const QString &text);
    // Every frame (or run of bytes that is none) as it passed, each way, as the recording has it.
    void framePassed(const share::RecordedFrame &frame);
    // A servo the traffic showed: once its model is known, and again once its whole identity
    // (addresses 0-8) is (ObservedServos::knownServo).
    void servoSeen(const feetech::ServoInfo &servo);
    // Sharing began (start succeeded) or ended (stop).
    void sharingChanged(bool sharing);

private:
    void onTransaction(const SharedTransaction &transaction);
    void onProgramBytes(const QByteArray &bytes);
    void followProgramRate();
    void onLinkStatus();
    void note(const QString &text);
    void raise(const ShareAlert &alert);
    // Into the recording; a recording the file refuses ends with a note, and the share goes on.
    void record(const RecordedFrame &frame);
    void announceServos();

    seriallink::LinkSession &m_link;
    seriallink::PseudoTerminal *m_terminal = nullptr;
    BusGate *m_gate = nullptr;
    ShareWatch *m_watch = nullptr;
    ObservedServos m_servos;
    ShareAlerts m_alerts;
    ShareRecording m_recording;
    QTimer m_ticks; // alerts that time raises
    QHash<quint8, bool> m_announced; // servos told of by servoSeen: whether with their identity
    qint32 m_programBaud = 0;
    bool m_portAway = false;
    bool m_sharing = false;
};

} // namespace share
