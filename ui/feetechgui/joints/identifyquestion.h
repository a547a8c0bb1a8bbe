// The question Identify asks before it wiggles a servo, the same from the joint table's buttons
// and from the Robot menu.
#pragma once

#include <QString>

class QWidget;

// True to go ahead: the user confirmed that `servo` ("ID 3 (STS3215)") may move, now or for
// good ("Don't ask again").
bool confirmIdentify(QWidget *parent, const QString &servo);
