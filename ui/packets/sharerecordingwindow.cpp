// A shared bus's recording as a table: the frames described as the live packet log does.
#include "sharerecordingwindow.h"

#include "hex.h"
#include "sharelogentries.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QFileInfo>
#include <QFontDatabase>
#include <QHeaderView>
#include <QLabel>
#include <QStandardItemModel>
#include <QTableView>
#include <QVBoxLayout>

ShareRecordingWindow::ShareRecordingWindow(const QString &path,
                                           const QVector<share::RecordedFrame> &frames,
                                           QWidget *parent)
    : QDialog(parent)
{
    setObjectName(QStringLiteral("shareRecordingWindow"));
    setAttribute(Qt::WA_DeleteOnClose);
    setWindowTitle(tr("Recording %1").arg(QFileInfo(path).fileName()));
    auto *about = new QLabel(tr("%n frame(s) and note(s) from %1, in the order they passed; the "
                                "time is seconds since sharing began.",
                                nullptr, int(frames.size()))
                                 .arg(QDir::toNativeSeparators(path)),
                             this);
    about->setObjectName(QStringLiteral("recordingAbout"));
    about->setWordWrap(true);

    m_model = new QStandardItemModel(0, ColumnCount, this);
    m_model->setHorizontalHeaderLabels(
        {tr("Time (s)"), tr("From"), tr("Bytes"), tr("Meaning"), tr("Error")});
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    share::ShareLogEntries entries;
    for (const share::RecordedFrame &frame : frames) {
        const seriallink::PacketLogEntry entry = entries.entry(frame, frame.timeUs / 1000);
        QList<QStandardItem *> row;
        row.append(new QStandardItem(QString::number(double(frame.timeUs) / 1e6, 'f', 6)));
        row.append(new QStandardItem(directionText(frame.direction)));
        auto *bytes = new QStandardItem(util::toHex(frame.bytes));
        bytes->setFont(fixed);
        row.append(bytes);
        row.append(new QStandardItem(entry.summary));
        row.append(new QStandardItem(entry.error));
        for (QStandardItem *item : std::as_const(row))
            item->setEditable(false);
        m_model->appendRow(row);
    }

    m_view = new QTableView(this);
    m_view->setObjectName(QStringLiteral("recordingView"));
    m_view->setModel(m_model);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->setShowGrid(false);
    m_view->verticalHeader()->hide();
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->horizontalHeader()->setSectionResizeMode(MeaningColumn, QHeaderView::Stretch);
    m_view->resizeColumnToContents(TimeColumn);
    m_view->resizeColumnToContents(FromColumn);
    m_view->setColumnWidth(BytesColumn, QFontMetrics(fixed).horizontalAdvance(QString(41, u'0')));

    auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(about);
    layout->addWidget(m_view, 1);
    layout->addWidget(buttons);
    resize(900, 500);
}

QString ShareRecordingWindow::directionText(share::FrameDirection direction)
{
    switch (direction) {
    case share::FrameDirection::FromProgram:
        return tr("program → bus");
    case share::FrameDirection::ToProgram:
        return tr("bus → program");
    case share::FrameDirection::Own:
        return tr("ServoBench → bus");
    case share::FrameDirection::OwnAnswer:
        return tr("bus → ServoBench");
    case share::FrameDirection::Note:
        return tr("note");
    }
    return {};
}
