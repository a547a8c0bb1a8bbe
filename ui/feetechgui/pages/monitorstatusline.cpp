// The Monitor page's status line, sized by its font's advance of the text.
#include "monitorstatusline.h"

#include <QEvent>
#include <QFontMetrics>

MonitorStatusLine::MonitorStatusLine(QWidget *parent)
    : QLabel(parent)
{
    setTextInteractionFlags(Qt::TextSelectableByMouse);
}

QSize MonitorStatusLine::sizeHint() const
{
    if (text().isEmpty())
        return QLabel::sizeHint(); // nothing to measure QLabel's margins against yet
    const int advance = QFontMetrics(font()).horizontalAdvance(text());
    if (!m_around) {
        const QSize measured = QLabel::sizeHint();
        m_around = QSize(measured.width() - advance, measured.height());
    }
    return {advance + m_around->width(), m_around->height()};
}

QSize MonitorStatusLine::minimumSizeHint() const
{
    return sizeHint(); // one line, never wrapped: QLabel's minimum is its size too
}

void MonitorStatusLine::changeEvent(QEvent *event)
{
    QLabel::changeEvent(event);
    if (event->type() == QEvent::FontChange || event->type() == QEvent::StyleChange)
        m_around.reset();
}
