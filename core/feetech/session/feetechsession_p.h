// The session's inside: its parts on the link and the state of its queue, which only the
// session and the OperationContext it hands to operations see.
#pragma once

#include "applyflow.h"
#include "busexchange.h"
#include "busoperation.h"
#include "busscan.h"
#include "busshare.h"
#include "guardkeeper.h"
#include "guidedflows.h"
#include "healthcheck.h"
#include "healthmovetest.h"
#include "jointidentify.h"
#include "motionreplay.h"
#include "motorsetup.h"
#include "sharelogentries.h"
#include "telemetrycycle.h"

#include <deque>

namespace seriallink {
class LinkSession;
}

namespace feetech {

struct SessionPrivate
{
    // An operation waiting for its turn, with the torque-off count when it was submitted.
    struct Queued
    {
        BusOperation operation;
        quint64 epoch = 0;
    };

    SessionTiming timing;
    FrameFormat format;
    // Made by the session, their parent.
    seriallink::LinkSession *link = nullptr;
    BusExchange *bus = nullptr;
    BusScan *scan = nullptr;
    GuidedFlows *flows = nullptr;
    TelemetryCycle *telemetry = nullptr;
    ApplyFlow *apply = nullptr;
    MotorSetup *motorSetup = nullptr;
    JointIdentify *identify = nullptr;
    MotionReplay *replay = nullptr;
    HealthCheck *health = nullptr;
    HealthMoveTest *moveTest = nullptr;
    GuardKeeper *guard = nullptr;
    share::BusShare *share = nullptr;
    share::ShareLogEntries shareLog; // the other program's frames, for the packet log

    std::deque<Queued> queue;
    bool running = false;
    Queued current; // the running one (its start function spent)
    bool paused = false; // the current operation waits in pauseFor
    Queued pausedOperation; // the one waiting, while paused
    quint64 pauseGeneration = 0; // a pause ended by a lost link never resumes
    quint64 torqueOffEpoch = 0; // counts torque-offs: a write queued before one is dropped
    bool identifying = false; // an identify runs, paused, or waits to go on
};

} // namespace feetech
