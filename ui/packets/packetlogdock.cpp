// The packet log dock: a table on PacketLogModel with a small tool bar.
#include "packetlogdock.h"

#include "packetlogmodel.h"
#include "palette.h"
#include "recentfiles.h"
#include "sharerecordingwindow.h"
#include "widgethelpers.h"

#include <QAction>
#include <QColor>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QFontDatabase>
#include <QHeaderView>
#include <QLabel>
#include <QMessageBox>
#include <QScrollBar>
#include <QSortFilterProxyModel>
#include <QStandardPaths>
#include <QStyle>
#include <QTableView>
#include <QToolBar>
#include <QVBoxLayout>

using seriallink::PacketLogModel;

// Presentation the core model must not know about (colours, fonts), plus the errors filter.
class PacketLogProxy : public QSortFilterProxyModel
{
public:
    using QSortFilterProxyModel::QSortFilterProxyModel;

    void setErrorsOnly(bool errorsOnly)
    {
        if (m_errorsOnly == errorsOnly)
            return;
        m_errorsOnly = errorsOnly;
        invalidateFilter();
    }
    bool errorsOnly() const { return m_errorsOnly; }

    void setErrorColor(const QColor &color) { m_errorColor = color; }
    void setHexFont(const QFont &font) { m_hexFont = font; }

    QVariant data(const QModelIndex &index, int role) const override
    {
        if (role == Qt::ForegroundRole && index.data(PacketLogModel::HasErrorRole).toBool())
            return m_errorColor;
        if (role == Qt::FontRole && index.column() == PacketLogModel::BytesColumn)
            return m_hexFont;
        return QSortFilterProxyModel::data(index, role);
    }

protected:
    bool filterAcceptsRow(int sourceRow, const QModelIndex &sourceParent) const override
    {
        if (!m_errorsOnly)
            return true;
        const QModelIndex index = sourceModel()->index(sourceRow, 0, sourceParent);
        return index.data(PacketLogModel::HasErrorRole).toBool();
    }

private:
    bool m_errorsOnly = false;
    QColor m_errorColor {Qt::red};
    QFont m_hexFont;
};

PacketLogDock::PacketLogDock(QWidget *parent)
    : QDockWidget(tr("Packet log"), parent)
{
    setObjectName(QStringLiteral("packetLogDock")); // QMainWindow::saveState() needs it
    setAllowedAreas(Qt::BottomDockWidgetArea | Qt::TopDockWidgetArea | Qt::RightDockWidgetArea);

    m_model = new PacketLogModel(this);
    m_proxy = new PacketLogProxy(this);
    m_proxy->setSourceModel(m_model);
    const QFont fixed = QFontDatabase::systemFont(QFontDatabase::FixedFont);
    m_proxy->setHexFont(fixed);

    auto *content = new QWidget(this);
    auto *layout = new QVBoxLayout(content);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);

    auto *toolBar = new QToolBar(content);
    toolBar->setObjectName(QStringLiteral("packetLogToolBar"));
    toolBar->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
    toolBar->setIconSize(QSize(16, 16));
    const auto addButton = [&](QAction *action, const char *name) {
        toolBar->addAction(action);
        toolBar->widgetForAction(action)->setObjectName(QLatin1String(name));
    };

    m_pause = new QAction(style()->standardIcon(QStyle::SP_MediaPause), tr("Pause"), this);
    m_pause->setObjectName(QStringLiteral("pauseLogAction"));
    m_pause->setCheckable(true);
    m_pause->setToolTip(tr("Freeze the log to read it; frames arriving meanwhile are kept "
                           "and appear when you resume"));
    connect(m_pause, &QAction::toggled, m_model, &PacketLogModel::setPaused);
    connect(m_pause, &QAction::toggled, this, &PacketLogDock::updateCounts);
    addButton(m_pause, "pauseLogButton");

    m_clear = new QAction(style()->standardIcon(QStyle::SP_DialogResetButton), tr("Clear"), this);
    m_clear->setObjectName(QStringLiteral("clearLogAction"));
    m_clear->setToolTip(tr("Remove every frame from the log and reset the counts"));
    connect(m_clear, &QAction::triggered, m_model, &PacketLogModel::clear);
    addButton(m_clear, "clearLogButton");

    m_export = new QAction(style()->standardIcon(QStyle::SP_DialogSaveButton), tr("Export…"), this);
    m_export->setObjectName(QStringLiteral("exportLogAction"));
    m_export->setToolTip(tr("Save the frames shown to a tab-separated text file"));
    connect(m_export, &QAction::triggered, this, &PacketLogDock::exportLog);
    addButton(m_export, "exportLogButton");

    m_openRecording = new QAction(style()->standardIcon(QStyle::SP_DialogOpenButton),
                                  tr("Open recording…"), this);
    m_openRecording->setObjectName(QStringLiteral("openRecordingAction"));
    m_openRecording->setToolTip(tr("Show a shared bus's recording (Link > Share this bus…) with "
                                   "the meaning of each frame"));
    connect(m_openRecording, &QAction::triggered, this, &PacketLogDock::chooseRecording);
    addButton(m_openRecording, "openRecordingButton");

    toolBar->addSeparator();
    m_errorsOnly = new QAction(tr("Errors only"), this);
    m_errorsOnly->setObjectName(QStringLiteral("errorsOnlyAction"));
    m_errorsOnly->setCheckable(true);
    m_errorsOnly->setToolTip(tr("Show only frames with an error (bad checksum, timeout, "
                                "unexpected bytes)"));
    connect(m_errorsOnly, &QAction::toggled, this, &PacketLogDock::setErrorsOnly);
    addButton(m_errorsOnly, "errorsOnlyButton");

    auto *spacer = new QWidget(toolBar);
    spacer->setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Preferred);
    toolBar->addWidget(spacer);
    m_counts = new QLabel(toolBar);
    m_counts->setObjectName(QStringLiteral("logCountLabel"));
    m_counts->setContentsMargins(6, 0, 6, 0);
    toolBar->addWidget(m_counts);
    layout->addWidget(toolBar);

    m_view = new QTableView(content);
    m_view->setObjectName(QStringLiteral("packetLogView"));
    m_view->setModel(m_proxy);
    m_view->setSelectionBehavior(QAbstractItemView::SelectRows);
    m_view->setAlternatingRowColors(true);
    m_view->setWordWrap(false);
    m_view->setShowGrid(false);
    m_view->setHorizontalScrollMode(QAbstractItemView::ScrollPerPixel);
    m_view->verticalHeader()->hide();
    // Fixed row heights: the view never measures twenty thousand rows.
    m_view->verticalHeader()->setSectionResizeMode(QHeaderView::Fixed);
    m_view->verticalHeader()->setDefaultSectionSize(
        std::max(fontMetrics().height(), QFontMetrics(fixed).height()) + 6);
    QHeaderView *header = m_view->horizontalHeader();
    header->setHighlightSections(false);
    const QFontMetrics metrics = fontMetrics();
    const int padding = 3 * style()->pixelMetric(QStyle::PM_FocusFrameHMargin) + 16;
    m_view->setColumnWidth(PacketLogModel::TimeColumn,
                           metrics.horizontalAdvance(QStringLiteral("00:00:00.000")) + padding);
    m_view->setColumnWidth(
        PacketLogModel::DirectionColumn,
        std::max(metrics.horizontalAdvance(tr("Direction")), metrics.horizontalAdvance(tr("→ out")))
            + padding);
    // Room for a PTK frame (10 bytes) and most Feetech packets without eliding.
    m_view->setColumnWidth(PacketLogModel::BytesColumn,
                           QFontMetrics(fixed).horizontalAdvance(QString(14 * 3 - 1, u'0'))
                               + padding);
    // The meaning is what people read: it takes the room the window has; errors are short.
    m_view->setColumnWidth(PacketLogModel::ErrorColumn, metrics.averageCharWidth() * 30);
    header->setStretchLastSection(false);
    header->setSectionResizeMode(PacketLogModel::MeaningColumn, QHeaderView::Stretch);
    // A few frames in sight however short the window (the meaning column stretches: no
    // horizontal scroll bar takes their place).
    widgethelpers::shrinkToRows(m_view, kLeastRows);
    layout->addWidget(m_view);
    setWidget(content);

    // Error rows readable on light and dark palettes alike.
    m_proxy->setErrorColor(palette::toneColor(palette::Tone::Error,
                                              palette::isDark(m_view->palette(), QPalette::Base)));

    QScrollBar *scroll = m_view->verticalScrollBar();
    connect(scroll, &QScrollBar::valueChanged, this,
            [this, scroll](int value) { m_atBottom = value >= scroll->maximum(); });
    connect(scroll, &QScrollBar::rangeChanged, this, &PacketLogDock::followNewRows);

    connect(m_model, &PacketLogModel::countsChanged, this, &PacketLogDock::showCounts);
    showCounts(m_model->totalCount(), m_model->errorCount());
}

void PacketLogDock::append(const seriallink::PacketLogEntry &entry)
{
    m_model->append(entry);
}

void PacketLogDock::followNewRows(int minimum, int maximum)
{
    Q_UNUSED(minimum);
    if (m_atBottom)
        m_view->verticalScrollBar()->setValue(maximum);
}

void PacketLogDock::setErrorsOnly(bool errorsOnly)
{
    m_proxy->setErrorsOnly(errorsOnly);
}

void PacketLogDock::showCounts(int total, int errors)
{
    m_shownTotal = total;
    m_shownErrors = errors;
    updateCounts();
}

void PacketLogDock::updateCounts()
{
    QString text = tr("%1, %2").arg(tr("%n frame(s)", nullptr, m_shownTotal),
                                    tr("%n error(s)", nullptr, m_shownErrors));
    if (m_model->isPaused())
        text = tr("%1 (paused)").arg(text);
    m_counts->setText(text);
    m_counts->setToolTip(m_model->isPaused()
                             ? tr("New frames are kept while paused and appear when you resume")
                             : m_model->rowCount() < m_shownTotal
                             ? tr("The log keeps the newest %n frame(s), errors longer; older "
                                  "ones were dropped",
                                  nullptr, m_model->capacity())
                                 + (m_model->droppedErrorCount() > 0 ? u'\n'
                                            + tr("%n older error(s) among them", nullptr,
                                                 m_model->droppedErrorCount())
                                                                     : QString())
                             : QString());
}

void PacketLogDock::exportLog()
{
    const QString suggested = recentfiles::suggestedPath(
        recentfiles::Kind::PacketLog,
        QStringLiteral("packet-log-%1.tsv")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-hhmmss"))));
    const QString path =
        QFileDialog::getSaveFileName(this, tr("Export packet log"), suggested,
                                     tr("Tab-separated text (*.tsv *.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    QString error;
    if (!m_model->exportToFile(path, &error))
        QMessageBox::warning(this, tr("Export packet log"), error);
    else
        recentfiles::add(recentfiles::Kind::PacketLog, path);
}

void PacketLogDock::chooseRecording()
{
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open a shared bus recording"),
                                     recentfiles::directory(recentfiles::Kind::ShareRecording),
                                     tr("Share recordings (*.txt);;All files (*)"));
    if (path.isEmpty())
        return;
    recentfiles::add(recentfiles::Kind::ShareRecording, path);
    QString error;
    if (!openRecording(path, &error))
        QMessageBox::warning(this, tr("Open recording"), error);
}

ShareRecordingWindow *PacketLogDock::openRecording(const QString &path, QString *error)
{
    util::FileError why;
    const auto frames = share::ShareRecording::load(path, &why);
    if (!frames) {
        if (error)
            *error = why.describe();
        return nullptr;
    }
    auto *window = new ShareRecordingWindow(path, *frames, this);
    window->show();
    window->raise();
    return window;
}
