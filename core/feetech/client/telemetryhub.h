// The GUI thread's telemetry: one stream of the servos every subscriber asks for, at the fastest
// rate any of them asks, and the newest sample of each servo.
#pragma once

#include "bustypes.h"
#include "refusal.h"
#include "telemetry.h"

#include <QHash>
#include <QObject>
#include <QVector>

#include <optional>
#include <vector>

namespace feetech {

class BusClient;

// Belongs to a BusClient (BusClient::telemetry()). Each subscriber (the Monitor page, the
// calibration wizard, a motion test) asks for its servos at its rate; the session streams the
// union, so none of them replaces or restores another's stream. A subscriber that is destroyed
// unsubscribes; a stream the session ends (the link went down) ends every subscription. While
// the bus is shared with another program the samples are those of the program's own reads.
class TelemetryHub : public QObject
{
    Q_OBJECT

public:
    explicit TelemetryHub(BusClient *client);

    // Asks for the feedback block of servos `indexes` at `rateHz` samples per second each (0:
    // as fast as the bus allows), replacing what `subscriber` asked before. A servo is taken
    // out after `missesBeforeMissing` missed cycles in a row (TelemetryOptions). False and
    // *refusal, and nothing changed, when it cannot be streamed.
    bool subscribe(const QObject *subscriber, const QVector<int> &indexes, double rateHz,
                   Refusal *refusal = nullptr,
                   int missesBeforeMissing = kDefaultMissesBeforeMissing);
    void unsubscribe(const QObject *subscriber);
    bool isSubscribed(const QObject *subscriber) const;

    bool isStreaming() const { return m_streaming; }
    // What streams now: the union of the subscriptions.
    const TelemetryOptions &options() const { return m_options; }
    bool isStreamed(int index) const;
    // The newest sample of servo `index` (nothing before the first).
    std::optional<FeedbackSample> latestSample(int index) const;
    const TelemetryStats &stats() const { return m_stats; }

signals:
    // Samples of the servos streamed, in batches (at most about 50 a second).
    void samplesReceived(const QVector<feetech::FeedbackSample> &samples);
    void statsChanged(const feetech::TelemetryStats &stats);
    void streamingChanged(bool streaming);

private:
    struct Subscription
    {
        const QObject *subscriber = nullptr;
        QVector<ServoInfo> servos;
        double rateHz = 0.0;
        int missesBeforeMissing = kDefaultMissesBeforeMissing;
    };
    // Streams the union of the subscriptions (a new stream only when it changed), or stops.
    void update();
    void stop();
    void onSamples(const QVector<FeedbackSample> &samples, quint64 stream);
    // What another program read of the feedback block on a shared bus (the session's own
    // cycles wait meanwhile): the newest of each servo, and the subscribers' servos passed on.
    void onSharedSamples(const QVector<FeedbackSample> &samples);
    void onStats(const TelemetryStats &stats);

    BusClient *m_client;
    std::vector<Subscription> m_subscriptions; // in the order they were first made
    bool m_streaming = false;
    quint64 m_stream = 0; // the stream asked for last; news of earlier ones is dropped
    TelemetryOptions m_options;
    TelemetryStats m_stats;
    QHash<ServoAddress, FeedbackSample> m_latest;
};

} // namespace feetech
