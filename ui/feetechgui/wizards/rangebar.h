// A joint's recorded range as a bar: one turn of the encoder, the range recorded so far filled,
// the present position marked.
#pragma once

#include <QWidget>

#include <optional>

class RangeBar : public QWidget
{
    Q_OBJECT

public:
    explicit RangeBar(QWidget *parent = nullptr);

    // Positions in steps, unwrapped (they may run past 0 or 4095); nothing before a sample.
    void setRange(std::optional<int> minimum, std::optional<int> present,
                  std::optional<int> maximum, bool lost);

    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    std::optional<int> m_minimum;
    std::optional<int> m_present;
    std::optional<int> m_maximum;
    bool m_lost = false;
};
