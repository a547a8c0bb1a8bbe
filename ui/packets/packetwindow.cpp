// Link > Packet window: build any Feetech instruction or PTK request, see its bytes with the
// checksum filled in, send it through the open connection, see what came back, resend it from
// the history, and save or load a sequence of frames.
#include "packetwindow.h"

#include "arguments.h"
#include "busclient.h"
#include "feetechpacket.h"
#include "hex.h"
#include "linkmirror.h"
#include "modeltable.h"
#include "ptkclient.h"
#include "ptkframe.h"
#include "ptkparameters.h"
#include "registertable.h"

#include <QComboBox>
#include <QDateTime>
#include <QFontDatabase>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QMessageBox>
#include <QPushButton>
#include <QSpinBox>
#include <QTabWidget>
#include <QTableWidget>
#include <QVBoxLayout>

namespace {

enum Column { TimeColumn, FrameColumn, MeaningColumn, OutcomeColumn, ColumnCount };
constexpr int kOtherCode = -1;
constexpr int kFeetechTab = 0;

using feetech::Instruction;

// Which fields an instruction uses.
struct Fields
{
    bool id = true;
    bool address = false;
    bool length = false;
    bool data = false;
    bool ids = false;
    bool code = false;
};

Fields fieldsOf(int code)
{
    switch (code) {
    case int(Instruction::Read):
        return {true, true, true, false, false, false};
    case int(Instruction::Write):
    case int(Instruction::RegWrite):
        return {true, true, false, true, false, false};
    case int(Instruction::SyncRead):
        return {false, true, true, false, true, false};
    case int(Instruction::SyncWrite):
        return {false, true, true, true, true, false};
    case int(Instruction::Calibrate):
        return {true, false, false, true, false, false};
    case kOtherCode:
        return {true, false, false, true, false, true};
    default:
        return {}; // PING, ACTION, RECOVERY, REBOOT, RESET: the ID alone
    }
}

QFont fixedFont()
{
    return QFontDatabase::systemFont(QFontDatabase::FixedFont);
}

} // namespace

PacketWindow::PacketWindow(feetech::BusClient *feetech, ptk::Client *ptk, QWidget *parent)
    : QDialog(parent)
    , m_feetech(feetech)
    , m_ptk(ptk)
{
    setWindowTitle(tr("Packet window"));
    setObjectName(QStringLiteral("packetWindow"));
    m_confirm = [this](const QString &risk) {
        return QMessageBox::question(this, tr("Send this frame?"), risk + u' ' + tr("Send it?"),
                                     QMessageBox::Yes | QMessageBox::Cancel, QMessageBox::Cancel)
            == QMessageBox::Yes;
    };

    m_tabs = new QTabWidget(this);
    m_tabs->addTab(buildFeetechPage(), tr("Feetech"));
    m_tabs->addTab(buildPtkPage(), tr("PTK"));
    connect(m_tabs, &QTabWidget::currentChanged, this, &PacketWindow::updatePreview);

    m_preview = new QLineEdit(this);
    m_preview->setObjectName(QStringLiteral("packetPreview"));
    m_preview->setReadOnly(true);
    m_preview->setFont(fixedFont());
    m_meaning = new QLabel(this);
    m_meaning->setObjectName(QStringLiteral("packetMeaning"));
    m_meaning->setWordWrap(true);
    m_send = new QPushButton(tr("Send"), this);
    m_send->setObjectName(QStringLiteral("sendPacketButton"));
    m_send->setDefault(true);
    connect(m_send, &QPushButton::clicked, this, [this] {
        QString error;
        const auto frame = builtFrame(&error);
        if (!frame || !send({*frame}, &error))
            showMessage(error, true);
    });
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("packetMessage"));
    m_message->setWordWrap(true);

    m_history = new QTableWidget(0, ColumnCount, this);
    m_history->setObjectName(QStringLiteral("packetHistory"));
    m_history->setHorizontalHeaderLabels({tr("Time"), tr("Frame"), tr("Meaning"), tr("Answer")});
    m_history->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_history->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_history->verticalHeader()->hide();
    m_history->horizontalHeader()->setStretchLastSection(true);
    m_history->setFont(fixedFont());
    connect(m_history, &QTableWidget::itemDoubleClicked, this, &PacketWindow::resendSelected);
    auto *resend = new QPushButton(tr("Resend"), this);
    resend->setObjectName(QStringLiteral("resendButton"));
    connect(resend, &QPushButton::clicked, this, &PacketWindow::resendSelected);
    auto *sendAll = new QPushButton(tr("Send all"), this);
    sendAll->setObjectName(QStringLiteral("sendAllButton"));
    sendAll->setToolTip(tr("Send every frame of the history again, oldest first"));
    connect(sendAll, &QPushButton::clicked, this, [this] {
        QString error;
        if (!send(m_frames, &error))
            showMessage(error, true);
    });
    m_sequenceFiles = new PacketSequenceFiles(m_frames, this);
    connect(m_sequenceFiles, &PacketSequenceFiles::loaded, this,
            [this](const QVector<PacketFrame> &frames) {
                for (const PacketFrame &frame : frames)
                    addHistoryRow(frame, tr("loaded, not sent"));
            });
    connect(m_sequenceFiles, &PacketSequenceFiles::reported, this, &PacketWindow::showMessage);
    auto *save = new QPushButton(tr("Save sequence…"), this);
    connect(save, &QPushButton::clicked, m_sequenceFiles, &PacketSequenceFiles::chooseSave);
    auto *load = new QPushButton(tr("Load sequence…"), this);
    connect(load, &QPushButton::clicked, m_sequenceFiles, &PacketSequenceFiles::chooseLoad);
    auto *clear = new QPushButton(tr("Clear"), this);
    connect(clear, &QPushButton::clicked, this, [this] {
        if (m_sending) {
            showMessage(tr("Wait until the frames on their way are answered."), true);
            return;
        }
        m_history->setRowCount(0);
        m_frames.clear();
        m_currentRow = -1;
    });

    auto *sendRow = new QHBoxLayout;
    sendRow->addWidget(m_preview, 1);
    sendRow->addWidget(m_send);
    auto *historyButtons = new QHBoxLayout;
    for (QPushButton *button : {resend, sendAll, save, load, clear})
        historyButtons->addWidget(button);
    historyButtons->addStretch();
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_tabs);
    layout->addLayout(sendRow);
    layout->addWidget(m_meaning);
    layout->addWidget(m_message);
    layout->addWidget(new QLabel(tr("History (double-click a frame to send it again):"), this));
    layout->addWidget(m_history, 1);
    layout->addLayout(historyButtons);

    connect(m_feetech->link(), &seriallink::LinkMirror::packetLogged, this,
            [this](const seriallink::PacketLogEntry &entry) {
                onLogged(PacketFrame::Protocol::Feetech, entry);
            });
    connect(m_ptk->link(), &seriallink::LinkMirror::packetLogged, this,
            [this](const seriallink::PacketLogEntry &entry) {
                onLogged(PacketFrame::Protocol::Ptk, entry);
            });
    connect(m_ptk, &ptk::Client::frameSent, this, [this](bool ok, const QString &message) {
        if (m_current.protocol == PacketFrame::Protocol::Ptk)
            finishCurrent(ok, message);
    });
    // All torque off stops a sequence too (a frame already queued is refused by the session).
    connect(m_feetech, &feetech::BusClient::allTorqueOffRequested, this,
            [this] { m_queue.clear(); });
    const auto watch = [this](seriallink::LinkMirror *link, PacketFrame::Protocol protocol) {
        connect(link, &seriallink::LinkMirror::statusChanged, this,
                [this, protocol](const seriallink::ConnectionStatus &status) {
                    // A PTK poll that timed out (No reply) leaves the frame queued: only a
                    // link closed or lost drops it.
                    const bool gone = status.state == seriallink::ConnectionState::Disconnected
                        || status.state == seriallink::ConnectionState::Lost;
                    if (m_sending && m_current.protocol == protocol && gone)
                        finishCurrent(false, tr("The connection closed."));
                    updatePreview();
                });
    };
    watch(m_feetech->link(), PacketFrame::Protocol::Feetech);
    watch(m_ptk->link(), PacketFrame::Protocol::Ptk);
    updateFields();
    resize(760, 620);
}

QWidget *PacketWindow::buildFeetechPage()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_instruction = new QComboBox(page);
    m_instruction->setObjectName(QStringLiteral("instructionCombo"));
    const struct
    {
        QString text;
        int code;
    } instructions[] = {
        {tr("PING"), int(Instruction::Ping)},
        {tr("READ"), int(Instruction::Read)},
        {tr("WRITE"), int(Instruction::Write)},
        {tr("REG WRITE"), int(Instruction::RegWrite)},
        {tr("ACTION"), int(Instruction::Action)},
        {tr("SYNC READ"), int(Instruction::SyncRead)},
        {tr("SYNC WRITE"), int(Instruction::SyncWrite)},
        {tr("RECOVERY (factory values)"), int(Instruction::Recovery)},
        {tr("REBOOT"), int(Instruction::Reboot)},
        {tr("RESET (clear the status)"), int(Instruction::Reset)},
        {tr("CALIBRATE (middle)"), int(Instruction::Calibrate)},
        {tr("Another code"), kOtherCode},
    };
    for (const auto &instruction : instructions)
        m_instruction->addItem(instruction.text, instruction.code);
    m_code = new QSpinBox(page);
    m_code->setObjectName(QStringLiteral("instructionCodeSpin"));
    m_code->setRange(0, 255);
    m_code->setDisplayIntegerBase(16);
    m_code->setPrefix(QStringLiteral("0x"));
    m_id = new QSpinBox(page);
    m_id->setObjectName(QStringLiteral("packetIdSpin"));
    m_id->setRange(0, feetech::kBroadcastId);
    m_id->setValue(1);
    m_id->setToolTip(tr("254 (0xFE) is the broadcast ID: every servo acts, none answers"));
    m_address = new QSpinBox(page);
    m_address->setObjectName(QStringLiteral("packetAddressSpin"));
    m_address->setRange(0, 255);
    m_length = new QSpinBox(page);
    m_length->setObjectName(QStringLiteral("packetLengthSpin"));
    m_length->setRange(1, feetech::kMaxPacketSize - feetech::kMinimumPacketSize - 2);
    m_length->setValue(2);
    m_data = new QLineEdit(page);
    m_data->setObjectName(QStringLiteral("packetDataEdit"));
    m_data->setFont(fixedFont());
    m_data->setPlaceholderText(tr("hex bytes, e.g. 00 08"));
    m_ids = new QLineEdit(page);
    m_ids->setObjectName(QStringLiteral("packetIdsEdit"));
    m_ids->setPlaceholderText(tr("e.g. 1,2,3 or 1-6"));
    m_baud = new QComboBox(page);
    m_baud->setObjectName(QStringLiteral("packetBaudCombo"));
    for (const qint32 baud : feetech::baudRates())
        m_baud->addItem(tr("%L1 bps").arg(baud), baud);
    m_baud->setCurrentIndex(m_baud->findData(1000000));

    form->addRow(tr("Instruction:"), m_instruction);
    form->addRow(tr("Code:"), m_code);
    form->addRow(tr("ID:"), m_id);
    form->addRow(tr("Address:"), m_address);
    form->addRow(tr("Length:"), m_length);
    form->addRow(tr("Data:"), m_data);
    form->addRow(tr("IDs:"), m_ids);
    form->addRow(tr("Baud rate:"), m_baud);
    connect(m_instruction, &QComboBox::currentIndexChanged, this, &PacketWindow::updateFields);
    for (QSpinBox *spin : {m_code, m_id, m_address, m_length})
        connect(spin, &QSpinBox::valueChanged, this, &PacketWindow::updatePreview);
    for (QLineEdit *edit : {m_data, m_ids})
        connect(edit, &QLineEdit::textChanged, this, &PacketWindow::updatePreview);
    connect(m_baud, &QComboBox::currentIndexChanged, this, &PacketWindow::updatePreview);
    return page;
}

QWidget *PacketWindow::buildPtkPage()
{
    auto *page = new QWidget(this);
    auto *form = new QFormLayout(page);
    m_ptkCommand = new QComboBox(page);
    m_ptkCommand->setObjectName(QStringLiteral("ptkCommandCombo"));
    for (const ptk::FrameLayout &query : ptk::queryLayouts())
        m_ptkCommand->addItem(
            tr("Query %1 (command %2)").arg(QLatin1String(query.name)).arg(query.command),
            query.command);
    for (const ptk::FrameLayout &write : ptk::writeLayouts())
        m_ptkCommand->addItem(
            tr("Write %1 (command %2)").arg(QLatin1String(write.name)).arg(write.command),
            write.command);
    m_ptkCommand->addItem(tr("Another command"), kOtherCode);
    m_ptkCode = new QSpinBox(page);
    m_ptkCode->setObjectName(QStringLiteral("ptkCodeSpin"));
    m_ptkCode->setRange(0, 255);
    m_word0 = new QSpinBox(page);
    m_word0->setObjectName(QStringLiteral("ptkWord0Spin"));
    m_word1 = new QSpinBox(page);
    m_word1->setObjectName(QStringLiteral("ptkWord1Spin"));
    for (QSpinBox *word : {m_word0, m_word1})
        word->setRange(0, 0xFFFF);
    form->addRow(tr("Command:"), m_ptkCommand);
    form->addRow(tr("Code:"), m_ptkCode);
    form->addRow(tr("First word:"), m_word0);
    form->addRow(tr("Second word:"), m_word1);
    form->addRow(new QLabel(tr("A query is answered with two words; the servo never "
                               "acknowledges a write. PTK servos talk at 115200 baud."),
                            page));
    connect(m_ptkCommand, &QComboBox::currentIndexChanged, this, &PacketWindow::updateFields);
    for (QSpinBox *spin : {m_ptkCode, m_word0, m_word1})
        connect(spin, &QSpinBox::valueChanged, this, &PacketWindow::updatePreview);
    return page;
}

void PacketWindow::updateFields()
{
    const Fields fields = fieldsOf(m_instruction->currentData().toInt());
    m_code->setEnabled(fields.code);
    m_id->setEnabled(fields.id);
    m_address->setEnabled(fields.address);
    m_length->setEnabled(fields.length);
    m_data->setEnabled(fields.data);
    m_ids->setEnabled(fields.ids);
    m_ptkCode->setEnabled(m_ptkCommand->currentData().toInt() == kOtherCode);
    updatePreview();
}

std::optional<PacketFrame> PacketWindow::builtFrame(QString *why) const
{
    const auto fail = [why](const QString &reason) -> std::optional<PacketFrame> {
        if (why)
            *why = reason;
        return std::nullopt;
    };
    if (m_tabs->currentIndex() != kFeetechTab) {
        const int chosen = m_ptkCommand->currentData().toInt();
        const ptk::Request request {quint8(chosen == kOtherCode ? m_ptkCode->value() : chosen),
                                    quint16(m_word0->value()), quint16(m_word1->value())};
        return packetsequence::ptkFrame(ptk::encodeRequest(request));
    }
    const int code = m_instruction->currentData().toInt();
    const Fields fields = fieldsOf(code);
    QString hexError;
    const auto data = util::parseHex(m_data->text(), &hexError);
    if (fields.data && !data)
        return fail(tr("Data: %1").arg(hexError));
    QVector<quint8> ids;
    if (fields.ids) {
        try {
            ids = cli::idList(m_ids->text(), feetech::kMaxServoId);
        } catch (const cli::UsageError &error) {
            return fail(error.message);
        }
    }
    const auto id = quint8(m_id->value());
    const auto address = quint8(m_address->value());
    const auto length = quint8(m_length->value());
    QByteArray bytes;
    switch (code) {
    case int(Instruction::Read):
        bytes = feetech::read(id, address, length);
        break;
    case int(Instruction::Write):
    case int(Instruction::RegWrite):
        if (data->isEmpty())
            return fail(tr("Data: give the bytes to write."));
        bytes = code == int(Instruction::Write) ? feetech::write(id, address, *data)
                                                : feetech::regWrite(id, address, *data);
        break;
    case int(Instruction::SyncRead):
        bytes = feetech::syncRead(address, length, ids);
        break;
    case int(Instruction::SyncWrite): {
        if (data->size() != length * ids.size())
            return fail(tr("Data: %n byte(s) for each of the %1 servo(s), one after the other.",
                           nullptr, length)
                            .arg(ids.size()));
        QVector<feetech::SyncWriteEntry> entries;
        for (int i = 0; i < ids.size(); ++i)
            entries.append({ids.at(i), data->mid(i * length, length)});
        bytes = feetech::syncWrite(address, length, entries).value_or(QByteArray());
        break;
    }
    case int(Instruction::Calibrate):
        if (!data->isEmpty() && data->size() != 2)
            return fail(tr("Data: none, or the 2-byte position to make the middle."));
        bytes = feetech::calibrate(id, *data);
        break;
    case kOtherCode:
        bytes = feetech::encodePacket(id, quint8(m_code->value()), *data);
        break;
    default:
        bytes = feetech::encodePacket(id, quint8(code));
        break;
    }
    if (bytes.size() > feetech::kMaxPacketSize)
        return fail(tr("The frame would be %1 bytes; a Feetech frame holds at most %2.")
                        .arg(bytes.size())
                        .arg(feetech::kMaxPacketSize));
    const auto frame = packetsequence::feetechFrame(bytes, m_baud->currentData().toInt());
    return frame ? frame : fail(tr("The fields do not make a whole frame."));
}

void PacketWindow::updatePreview()
{
    QString why;
    const auto frame = builtFrame(&why);
    m_preview->setText(frame ? util::toHex(frame->bytes) : QString());
    m_meaning->setText(frame ? packetsequence::describe(*frame) : why);
    const bool feetech = m_tabs->currentIndex() == kFeetechTab;
    const bool open = feetech ? m_feetech->link()->isConnected() : m_ptk->isConnected();
    m_send->setEnabled(frame.has_value() && open && !m_sending);
    m_send->setToolTip(open          ? QString()
                           : feetech ? tr("Connect to a Feetech bus first")
                                     : tr("Connect to a PTK servo first"));
}

void PacketWindow::setConfirm(std::function<bool(const QString &risk)> confirm)
{
    m_confirm = std::move(confirm);
}

bool PacketWindow::send(const QVector<PacketFrame> &frames, QString *error)
{
    const auto fail = [error](const QString &reason) {
        if (error)
            *error = reason;
        return false;
    };
    if (m_sending)
        return fail(tr("Wait until the frames on their way are answered."));
    if (frames.isEmpty())
        return fail(tr("There is nothing to send."));
    for (const PacketFrame &frame : frames) {
        const bool feetech = frame.protocol == PacketFrame::Protocol::Feetech;
        if (feetech ? !m_feetech->link()->isConnected() : !m_ptk->isConnected())
            return fail(feetech ? tr("Connect to a Feetech bus first.")
                                : tr("Connect to a PTK servo first."));
    }
    QStringList risks;
    for (const PacketFrame &frame : frames) {
        const QString risk = packetsequence::riskOf(frame);
        if (!risk.isEmpty() && !risks.contains(risk))
            risks.append(risk);
    }
    if (!risks.isEmpty() && !m_confirm(risks.join(u' ')))
        return fail(tr("Nothing was sent."));
    m_queue = frames;
    m_sending = true;
    sendNext();
    return true;
}

void PacketWindow::sendNext()
{
    if (m_queue.isEmpty()) {
        m_sending = false;
        updatePreview();
        return;
    }
    const PacketFrame frame = m_queue.takeFirst();
    addHistoryRow(frame, tr("sending…"));
    m_currentRow = m_history->rowCount() - 1;
    m_current = frame;
    m_currentSeen = false;
    QString error;
    bool accepted = false;
    if (frame.protocol == PacketFrame::Protocol::Feetech) {
        feetech::Refusal refusal;
        feetech::OperationReply *reply = m_feetech->commands()->sendPacket(
            frame.bytes, frame.baud, frame.replyId, frame.replyDataSize, &refusal);
        error = refusal.describe();
        if (reply)
            connect(reply, &feetech::OperationReply::finished, this,
                    &PacketWindow::onFeetechFinished);
        accepted = reply;
    } else {
        accepted = m_ptk->sendFrame(frame.bytes, frame.expectsReply, &error);
    }
    updatePreview();
    if (!accepted)
        finishCurrent(false, error);
}

void PacketWindow::onFeetechFinished(const feetech::OperationResult &result)
{
    if (m_current.protocol == PacketFrame::Protocol::Feetech)
        finishCurrent(result.ok, result.message);
}

void PacketWindow::finishCurrent(bool ok, const QString &message)
{
    if (!m_sending)
        return;
    if (m_currentRow >= 0 && m_currentRow < m_history->rowCount()) {
        QTableWidgetItem *outcome = m_history->item(m_currentRow, OutcomeColumn);
        const QString answers = outcome->data(Qt::UserRole).toString();
        outcome->setText(answers.isEmpty() ? message : answers);
        outcome->setToolTip(message);
        if (!ok)
            outcome->setForeground(palette().brush(QPalette::Disabled, QPalette::Text));
    }
    showMessage(message, !ok);
    m_currentRow = -1;
    emit sent(ok, message);
    if (!ok)
        m_queue.clear(); // a sequence stops at its first failure
    sendNext();
}

void PacketWindow::onLogged(PacketFrame::Protocol link, const seriallink::PacketLogEntry &entry)
{
    // On the frame's own link, what arrives after the frame itself went out is its answer (or a
    // stray the log marks); a poll or an operation queued ahead of it comes before.
    if (!m_sending || m_currentRow < 0 || link != m_current.protocol)
        return;
    if (entry.direction == seriallink::Direction::Out) {
        m_currentSeen = m_currentSeen || entry.bytes == m_current.bytes;
        return;
    }
    if (!m_currentSeen || entry.direction != seriallink::Direction::In)
        return;
    QTableWidgetItem *outcome = m_history->item(m_currentRow, OutcomeColumn);
    QString answers = outcome->data(Qt::UserRole).toString();
    const QString line = util::toHex(entry.bytes) + QStringLiteral(": ")
        + (entry.error.isEmpty() ? entry.summary : entry.error);
    answers += (answers.isEmpty() ? QString() : QStringLiteral("\n")) + line;
    outcome->setData(Qt::UserRole, answers);
    outcome->setText(answers);
}

void PacketWindow::addHistoryRow(const PacketFrame &frame, const QString &outcome)
{
    const int row = m_history->rowCount();
    m_history->insertRow(row);
    m_history->setItem(
        row, TimeColumn,
        new QTableWidgetItem(QTime::currentTime().toString(QStringLiteral("HH:mm:ss.zzz"))));
    m_history->setItem(row, FrameColumn, new QTableWidgetItem(util::toHex(frame.bytes)));
    m_history->setItem(row, MeaningColumn, new QTableWidgetItem(packetsequence::describe(frame)));
    m_history->setItem(row, OutcomeColumn, new QTableWidgetItem(outcome));
    m_history->resizeColumnToContents(FrameColumn);
    m_history->resizeColumnToContents(MeaningColumn);
    m_history->scrollToBottom();
    m_frames.append(frame);
}

void PacketWindow::resendSelected()
{
    const int row = m_history->currentRow();
    if (row < 0 || row >= m_frames.size()) {
        showMessage(tr("Choose a frame of the history first."), true);
        return;
    }
    QString error;
    if (!send({m_frames.at(row)}, &error))
        showMessage(error, true);
}

void PacketWindow::showMessage(const QString &text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("QLabel { color: #b00020; }") : QString());
}
