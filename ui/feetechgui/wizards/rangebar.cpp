// The range bar: one encoder turn centred on the middle of the recorded range.
#include "rangebar.h"

#include "armcalibration.h"
#include "palette.h"

#include <QPainter>

#include <algorithm>

RangeBar::RangeBar(QWidget *parent)
    : QWidget(parent)
{
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
}

void RangeBar::setRange(std::optional<int> minimum, std::optional<int> present,
                        std::optional<int> maximum, bool lost)
{
    m_minimum = minimum;
    m_present = present;
    m_maximum = maximum;
    m_lost = lost;
    update();
}

QSize RangeBar::sizeHint() const
{
    return {360, 22};
}

QSize RangeBar::minimumSizeHint() const
{
    return {120, 18};
}

void RangeBar::paintEvent(QPaintEvent *)
{
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QRectF track = QRectF(rect()).adjusted(1, 3, -1, -3);
    painter.setPen(palette().color(QPalette::Mid));
    painter.setBrush(palette().color(QPalette::Base));
    painter.drawRoundedRect(track, 3, 3);
    // The turn shown is centred on the middle of the range, as the calibration will centre it:
    // a range that crosses the seam shows whole.
    const int middle = m_minimum && m_maximum ? (*m_minimum + *m_maximum) / 2
                                              : m_present.value_or(feetech::kEncoderMiddle);
    const double first = middle - feetech::kEncoderSteps / 2.0;
    const auto x = [&](int steps) {
        return track.left()
            + track.width() * std::clamp((steps - first) / feetech::kEncoderSteps, 0.0, 1.0);
    };
    const QColor accent =
        palette::toneColor(m_lost ? palette::Tone::Error : palette::Tone::Accent, palette());
    if (m_minimum && m_maximum) {
        QColor fill = accent;
        fill.setAlpha(110);
        painter.setPen(Qt::NoPen);
        painter.setBrush(fill);
        painter.drawRect(QRectF(QPointF(x(*m_minimum), track.top() + 1),
                                QPointF(x(*m_maximum), track.bottom() - 1)));
    }
    // The middle of the turn: where the middle of the range goes.
    QColor middleColour = palette().color(QPalette::Text);
    middleColour.setAlpha(140);
    painter.setPen(QPen(middleColour, 1, Qt::DashLine));
    painter.drawLine(QPointF(track.center().x(), track.top()),
                     QPointF(track.center().x(), track.bottom()));
    if (m_present) {
        painter.setPen(QPen(palette().color(QPalette::Text), 3));
        painter.drawLine(QPointF(x(*m_present), rect().top()),
                         QPointF(x(*m_present), rect().bottom()));
    }
}
