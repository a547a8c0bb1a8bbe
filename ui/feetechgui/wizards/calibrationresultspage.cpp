// The calibration wizard's results page: the table of offsets and limits, and its buttons.
#include "calibrationresultspage.h"

#include "palette.h"
#include "robottemplate.h"
#include "widgethelpers.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QTableWidget>
#include <QTimer>
#include <QVBoxLayout>

namespace {

enum ResultColumn { JointColumn, OffsetColumn, MinimumColumn, MaximumColumn, StatusColumn };

} // namespace

CalibrationResultsPage::CalibrationResultsPage(QWidget *parent)
    : QWidget(parent)
{
    QWidget *page = this;
    auto *layout = new QVBoxLayout(page);
    m_summary = widgethelpers::wrappedLabel(QString(), page);
    m_summary->setObjectName(QStringLiteral("calibrationResultsSummary"));
    layout->addWidget(m_summary);
    m_table = new QTableWidget(0, 5, page);
    m_table->setObjectName(QStringLiteral("calibrationResultTable"));
    m_table->setHorizontalHeaderLabels(
        {tr("Joint"), tr("Offset"), tr("Min limit"), tr("Max limit"), tr("Status")});
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    m_table->setWordWrap(true);
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    layout->addWidget(m_table, 1);
    m_progress = new QProgressBar(page);
    m_progress->setObjectName(QStringLiteral("calibrationProgress"));
    m_progress->hide();
    layout->addWidget(m_progress);
    m_write = widgethelpers::actionButton(tr("&Write to the servos"), "writeCalibrationButton",
                                          tr("Write the offsets and limits to EEPROM and verify "
                                             "them"),
                                          page);
    m_save = widgethelpers::actionButton(tr("&Save LeRobot file…"), "saveLeRobotFileButton",
                                         tr("Save the written calibration as LeRobot's JSON file"),
                                         page);
    m_save->setEnabled(false);
    m_again =
        widgethelpers::actionButton(tr("&Record again"), "recordAgainButton",
                                    tr("Forget this recording and record the ranges again"), page);
    auto *buttons = new QHBoxLayout;
    buttons->addWidget(m_again);
    buttons->addStretch(1);
    buttons->addWidget(m_write);
    buttons->addWidget(m_save);
    layout->addLayout(buttons);
}

void CalibrationResultsPage::showResults(const QVector<feetech::JointCalibration> &results)
{
    palette::showInTone(m_summary,
                        tr("Each joint's new position offset and angle limits (in steps, in the "
                           "new coordinates), or why it is refused. Nothing has been written "
                           "yet."),
                        palette::Tone::Accent);
    m_table->setRowCount(int(results.size()));
    const QColor refused = palette::toneColor(palette::Tone::Error, m_table->palette());
    for (int row = 0; row < results.size(); ++row) {
        const feetech::JointCalibration &result = results.at(row);
        m_table->setItem(
            row, JointColumn,
            new QTableWidgetItem(
                tr("%1 (%2)").arg(feetech::jointDisplayName(result.name)).arg(result.id)));
        const auto number = [&result](qint32 value) {
            return new QTableWidgetItem(result.ok() ? QString::number(value) : QString());
        };
        m_table->setItem(row, OffsetColumn, number(result.offset));
        m_table->setItem(row, MinimumColumn, number(result.minimumLimit));
        m_table->setItem(row, MaximumColumn, number(result.maximumLimit));
        auto *status = new QTableWidgetItem(
            result.ok() ? tr("To write") : tr("Refused, nothing written: %1").arg(result.refusal));
        status->setToolTip(status->text());
        if (!result.ok())
            status->setForeground(refused);
        m_table->setItem(row, StatusColumn, status);
    }
    m_table->resizeColumnsToContents();
    m_table->horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    // Once the stretched column has its width, long refusals wrap onto more lines.
    QTimer::singleShot(0, m_table, [table = m_table] { table->resizeRowsToContents(); });
}

void CalibrationResultsPage::showWritten(int row, bool ok, const QString &message)
{
    auto *status = new QTableWidgetItem(ok ? tr("Written and verified") : message);
    if (!ok)
        status->setForeground(palette::toneColor(palette::Tone::Error, m_table->palette()));
    m_table->setItem(row, StatusColumn, status);
}

void CalibrationResultsPage::showWriting()
{
    palette::showInTone(m_summary,
                        tr("Writing each joint's offset and limits to its EEPROM and reading "
                           "them back…"),
                        palette::Tone::Accent);
}

void CalibrationResultsPage::showWriteOutcome(int verified, int total)
{
    if (verified == total) {
        palette::showInTone(m_summary,
                            tr("Every joint's offset and limits were written to its EEPROM and "
                               "read back as written."),
                            palette::Tone::Good);
    } else if (verified == 0) {
        palette::showInTone(m_summary,
                            tr("No joint's calibration was written and verified: the status "
                               "column says why."),
                            palette::Tone::Error);
    } else {
        palette::showInTone(m_summary,
                            tr("%1 of %n joint(s) were written and verified; the status column "
                               "says what became of the others.",
                               nullptr, total)
                                .arg(verified),
                            palette::Tone::Warning);
    }
}
