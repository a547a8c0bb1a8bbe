// Readouts of the Monitor page: the newest sample and the rate of each servo, drawn on demand.
#include "monitorreadouts.h"

#include "busclient.h"
#include "widgethelpers.h"

#include <QEvent>
#include <QFontMetrics>
#include <QHeaderView>
#include <QLocale>
#include <QStyle>

#include <algorithm>

namespace {

// Per-servo samples per second are counted over this span.
constexpr qint64 kRateSpanUs = 1000000;

// Decimals worth showing for each quantity, in its unit.
int decimals(feetech::Quantity quantity)
{
    switch (quantity) {
    case feetech::Quantity::Load:
    case feetech::Quantity::Voltage:
        return 1;
    default:
        return 0;
    }
}

} // namespace

MonitorReadouts::MonitorReadouts(feetech::BusClient *client, QWidget *parent)
    : QTableWidget(0, ColumnCount, parent)
    , m_client(client)
{
    setObjectName(QStringLiteral("monitorReadouts"));
    QStringList headers {tr("Servo")};
    for (const feetech::Quantity quantity : feetech::kAllQuantities) {
        headers.append(
            tr("%1 (%2)").arg(feetech::quantityName(quantity), feetech::quantityUnit(quantity)));
    }
    headers << tr("Moving") << tr("Status") << tr("Samples/s") << tr("Missed") << tr("State");
    setHorizontalHeaderLabels(headers);
    horizontalHeaderItem(StatusColumn)
        ->setToolTip(tr("The servo's protection bits that tripped (register 65)"));
    horizontalHeaderItem(MissedColumn)
        ->setToolTip(tr("Cycles in which the servo was asked and did not answer"));
    verticalHeader()->hide();
    verticalHeader()->setDefaultSectionSize(fontMetrics().height() + 6);
    // A few servos in sight however short the window, above the scroll bar the columns need.
    widgethelpers::shrinkToRows(this, kLeastRows);
    setMinimumHeight(minimumHeight() + style()->pixelMetric(QStyle::PM_ScrollBarExtent));
    setEditTriggers(QAbstractItemView::NoEditTriggers);
    setSelectionBehavior(QAbstractItemView::SelectRows);
    setAlternatingRowColors(true);
    setWordWrap(false);
    // Not ResizeToContents: that measures every cell of every column again for each cell whose
    // text changes, which made these readouts cost more than the plot. fitColumns measures
    // only the texts, once per refresh.
    horizontalHeader()->setSectionResizeMode(QHeaderView::Interactive);
    horizontalHeader()->setSectionResizeMode(StatusColumn, QHeaderView::Stretch);
    resizeColumnsToContents();
}

void MonitorReadouts::addSample(const feetech::FeedbackSample &sample)
{
    Latest &latest = m_latest[feetech::ServoAddress {sample.id, sample.baud}];
    if (sample.steadyUs >= latest.sample.steadyUs)
        latest.sample = sample;
    latest.recent.push_back(sample.steadyUs);
    while (!latest.recent.empty() && latest.recent.front() <= sample.steadyUs - kRateSpanUs)
        latest.recent.pop_front();
}

void MonitorReadouts::clearSamples()
{
    m_latest.clear();
}

void MonitorReadouts::refresh(const QVector<Row> &rows, const feetech::TelemetryStats &stats,
                              bool running)
{
    if (rowCount() != rows.size()) {
        setRowCount(int(rows.size()));
        m_neededWidths.fill(-1);
    }
    const qint64 now = feetech::steadyMicroseconds();
    const QLocale locale;
    const QString none = tr("—");
    for (int row = 0; row < rows.size(); ++row) {
        const feetech::ServoAddress &key = rows.at(row).key;
        const auto latest = m_latest.find(key);
        const feetech::FeedbackSample *sample =
            latest != m_latest.end() && latest->sample.steadyUs != 0 ? &latest->sample : nullptr;
        const feetech::ServoTelemetry *health = nullptr;
        for (const feetech::ServoTelemetry &servo : std::as_const(stats.servos)) {
            if (feetech::ServoAddress {servo.id, servo.baud} == key)
                health = &servo;
        }

        QStringList cells(ColumnCount);
        cells[ServoColumn] =
            rows.at(row).name.isEmpty() ? tr("ID %1").arg(key.id) : rows.at(row).name;
        for (int q = 0; q < feetech::kQuantityCount; ++q) {
            const auto value = sample ? sample->values.at(std::size_t(q)) : std::nullopt;
            cells[PositionColumn + q] =
                value ? locale.toString(*value, 'f', decimals(feetech::kAllQuantities[q])) : none;
        }
        cells[MovingColumn] = sample ? (sample->moving ? tr("yes") : tr("no")) : none;
        cells[StatusColumn] = sample ? statusText(key, sample->servoStatus) : none;
        if (latest != m_latest.end() && running) {
            while (!latest->recent.empty() && latest->recent.front() <= now - kRateSpanUs)
                latest->recent.pop_front();
            cells[RateColumn] = locale.toString(qint64(latest->recent.size()));
        } else {
            cells[RateColumn] = none;
        }
        cells[MissedColumn] = health ? locale.toString(health->missed) : none;
        bool missing = false;
        if (health && health->missing) {
            cells[StateColumn] = tr("Not answering");
            missing = true;
        } else if (!running) {
            cells[StateColumn] = sample ? tr("Stopped") : none;
        } else if (!sample) {
            cells[StateColumn] = tr("Waiting");
        } else {
            cells[StateColumn] = tr("OK");
        }

        for (int column = 0; column < ColumnCount; ++column) {
            QTableWidgetItem *cell = item(row, column);
            if (!cell) {
                cell = new QTableWidgetItem;
                const bool text = column == ServoColumn || column == StatusColumn
                    || column == StateColumn || column == MovingColumn;
                cell->setTextAlignment(Qt::Alignment(text ? Qt::AlignLeft : Qt::AlignRight)
                                       | Qt::AlignVCenter);
                setItem(row, column, cell);
            }
            if (cell->text() != cells.at(column)) {
                cell->setText(cells.at(column));
                m_neededWidths[column] = -1;
            }
        }
        // A tripped protection bit or a servo that stopped answering must catch the eye.
        const bool tripped = sample && sample->servoStatus != 0;
        QTableWidgetItem *status = item(row, StatusColumn);
        status->setForeground(tripped ? QBrush(kProblemColour) : QBrush());
        QTableWidgetItem *state = item(row, StateColumn);
        state->setForeground(missing ? QBrush(kProblemColour) : QBrush());
        if (state->font().bold() != missing) {
            QFont font = state->font();
            font.setBold(missing);
            state->setFont(font);
            m_neededWidths[StateColumn] = -1;
        }
        QTableWidgetItem *servo = item(row, ServoColumn);
        const QColor colour = rows.at(row).colour;
        servo->setForeground(colour.isValid() ? QBrush(colour) : QBrush());
        servo->setBackground(missing ? QBrush(QColor(0xfd, 0xe2, 0xe2)) : QBrush());
        servo->setToolTip(tr("ID %1 at %2").arg(key.id).arg(feetech::baudText(key.baud)));
    }
    fitColumns();
}

void MonitorReadouts::fitColumns()
{
    // The item delegate's padding either side of a cell's text.
    const int padding =
        2 * (style()->pixelMetric(QStyle::PM_FocusFrameHMargin, nullptr, this) + 1) + 4;
    for (int column = 0; column < ColumnCount; ++column) {
        if (column == StatusColumn)
            continue; // stretches over what is left
        int &needed = m_neededWidths[column];
        if (needed < 0) {
            needed = horizontalHeader()->sectionSizeHint(column);
            for (int row = 0; row < rowCount(); ++row) {
                const QTableWidgetItem *cell = item(row, column);
                if (!cell)
                    continue;
                const QFontMetrics metrics(cell->font());
                needed = std::max(needed, metrics.horizontalAdvance(cell->text()) + padding);
            }
        }
        if (needed > columnWidth(column))
            setColumnWidth(column, needed);
    }
}

void MonitorReadouts::changeEvent(QEvent *event)
{
    QTableWidget::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange
        || event->type() == QEvent::LanguageChange)
        m_neededWidths.fill(-1); // the texts measure otherwise now
}

QString MonitorReadouts::statusText(const feetech::ServoAddress &key, quint8 bits) const
{
    const int index = m_client ? m_client->servos()->indexOf(key) : -1;
    if (index >= 0)
        return feetech::servoStatusText(m_client->servos()->at(index).info.table(), bits);
    return bits == 0 ? tr("none") : QStringLiteral("0x%1").arg(bits, 2, 16, QLatin1Char('0'));
}
