// The Control page's guard banner: what the overload and thermal guard last said about the servo
// shown, with the guard's settings and the recovery of a tripped overload at hand.
#pragma once

#include "bustypes.h"

#include <QFrame>
#include <QPointer>

#include <optional>

class QLabel;
class QPushButton;

namespace feetech {
class BusClient;
struct GuardEvent;
} // namespace feetech

class GuardBanner : public QFrame
{
    Q_OBJECT

public:
    explicit GuardBanner(feetech::BusClient *client, QWidget *parent = nullptr);

    // The servo shown, as BusClient numbers them; -1: none (the banner hides).
    void setServo(int index);

    // What the guard last said about the servo shown (empty: nothing).
    QString text() const;

private:
    void onServosChanged();
    void onGuardEvent(const feetech::GuardEvent &event);
    void showGuard();
    void openGuardSettings();
    void openRecovery();

    QPointer<feetech::BusClient> m_client; // the main window may delete it before its pages
    int m_index = -1;
    std::optional<feetech::ServoAddress> m_servo; // the servo shown

    QLabel *m_text = nullptr;
    QPushButton *m_recover = nullptr;
    QPushButton *m_settings = nullptr;
};
