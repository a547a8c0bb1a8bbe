// Link > Packet window: build any Feetech instruction or PTK request, see its bytes with the
// checksum filled in, send it through the open connection, see what came back, resend it from
// the history, and save or load a sequence of frames.
#pragma once

#include "packetsequence.h"
#include "packetsequencefiles.h"

#include <QDialog>

class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSpinBox;
class QTableWidget;
class QTabWidget;

namespace feetech {
class BusClient;
struct OperationResult;
} // namespace feetech
namespace ptk {
class Client;
}
namespace seriallink {
struct PacketLogEntry;
}

class PacketWindow : public QDialog
{
    Q_OBJECT

public:
    PacketWindow(feetech::BusClient *feetech, ptk::Client *ptk, QWidget *parent = nullptr);

    // The frame the form describes now; nothing (and *why) when it cannot be built.
    std::optional<PacketFrame> builtFrame(QString *why = nullptr) const;
    // Sends `frames` one after the other, asking first when one of them is risky. `confirm`
    // stands in for that question in tests. False (and *error) when nothing was sent.
    bool send(const QVector<PacketFrame> &frames, QString *error = nullptr);
    void setConfirm(std::function<bool(const QString &risk)> confirm);
    bool isSending() const { return m_sending; }

    QTableWidget *history() const { return m_history; }
    QVector<PacketFrame> historyFrames() const { return m_frames; }
    // Where the history is saved to and loaded from.
    PacketSequenceFiles *sequenceFiles() const { return m_sequenceFiles; }

signals:
    void sent(bool ok, const QString &message); // each frame, once its outcome is known

private:
    QWidget *buildFeetechPage();
    QWidget *buildPtkPage();
    void updatePreview();
    void updateFields();
    void sendNext();
    void finishCurrent(bool ok, const QString &message);
    void onLogged(PacketFrame::Protocol link, const seriallink::PacketLogEntry &entry);
    void onFeetechFinished(const feetech::OperationResult &result);
    void addHistoryRow(const PacketFrame &frame, const QString &outcome);
    void resendSelected();
    void showMessage(const QString &text, bool error);

    feetech::BusClient *m_feetech = nullptr;
    ptk::Client *m_ptk = nullptr;
    std::function<bool(const QString &)> m_confirm;

    QTabWidget *m_tabs = nullptr;
    // Feetech
    QComboBox *m_instruction = nullptr;
    QSpinBox *m_code = nullptr; // another instruction code
    QSpinBox *m_id = nullptr;
    QSpinBox *m_address = nullptr;
    QSpinBox *m_length = nullptr;
    QLineEdit *m_data = nullptr;
    QLineEdit *m_ids = nullptr;
    QComboBox *m_baud = nullptr;
    // PTK
    QComboBox *m_ptkCommand = nullptr;
    QSpinBox *m_ptkCode = nullptr;
    QSpinBox *m_word0 = nullptr;
    QSpinBox *m_word1 = nullptr;

    QLineEdit *m_preview = nullptr;
    QLabel *m_meaning = nullptr;
    QPushButton *m_send = nullptr;
    QLabel *m_message = nullptr;
    QTableWidget *m_history = nullptr;
    QVector<PacketFrame> m_frames; // the history's rows, oldest first
    PacketSequenceFiles *m_sequenceFiles = nullptr;

    QVector<PacketFrame> m_queue; // still to send
    bool m_sending = false;
    int m_currentRow = -1; // the history row of the frame in flight
    PacketFrame m_current; // the frame in flight
    bool m_currentSeen = false; // its own bytes went by in its link's log: answers follow
};
