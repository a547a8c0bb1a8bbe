// One telemetry stream for every subscriber: the union of their servos at the fastest rate.
#include "telemetryhub.h"

#include "busclient.h"
#include "busshare.h"

#include <algorithm>

namespace {

bool sameServo(const feetech::ServoInfo &a, const feetech::ServoInfo &b)
{
    return a.address() == b.address();
}

bool sameServos(const QVector<feetech::ServoInfo> &a, const QVector<feetech::ServoInfo> &b)
{
    return std::equal(a.begin(), a.end(), b.begin(), b.end(), sameServo);
}

} // namespace

namespace feetech {

TelemetryHub::TelemetryHub(BusClient *client)
    : QObject(client)
    , m_client(client)
{
    Session *session = client->session();
    connect(session, &Session::telemetry, this, &TelemetryHub::onSamples);
    connect(session, &Session::telemetryStats, this, &TelemetryHub::onStats);
    connect(&session->share(), &share::BusShare::feedbackSeen, this,
            &TelemetryHub::onSharedSamples);
    // Samples belong to the servos as scanned: a new list starts without them.
    connect(client->servos(), &ServoList::servosChanged, this, [this] { m_latest.clear(); });
}

bool TelemetryHub::subscribe(const QObject *subscriber, const QVector<int> &indexes, double rateHz,
                             Refusal *refusal, int missesBeforeMissing)
{
    const auto refuse = [refusal](const Refusal &why) {
        refused(why, refusal);
        return false;
    };
    if (!m_client->link()->isConnected())
        return refuse(Refusal(Refusal::Code::NotConnected));
    if (indexes.isEmpty())
        return refuse(Refusal(Refusal::Code::NoServoToMonitor));
    if (rateHz < 0)
        return refuse(Refusal(Refusal::Code::NegativeRate));
    Subscription subscription {subscriber, {}, rateHz, std::max(1, missesBeforeMissing)};
    for (const int index : indexes) {
        if (index < 0 || index >= m_client->servos()->count())
            return refuse(Refusal(Refusal::Code::NoServo));
        const ServoInfo &info = m_client->servos()->at(index).info;
        if (!info.hasTable())
            return refuse(Refusal::undecodableFeedback(info.id));
        subscription.servos.append(info);
    }
    const auto known = std::find_if(
        m_subscriptions.begin(), m_subscriptions.end(),
        [subscriber](const Subscription &each) { return each.subscriber == subscriber; });
    if (known != m_subscriptions.end()) {
        *known = subscription;
    } else {
        m_subscriptions.push_back(subscription);
        // Half destroyed, it must hear nothing more: the stream changes once it is gone.
        connect(subscriber, &QObject::destroyed, this, [this, subscriber] {
            const auto gone = std::find_if(
                m_subscriptions.begin(), m_subscriptions.end(),
                [subscriber](const Subscription &each) { return each.subscriber == subscriber; });
            if (gone == m_subscriptions.end())
                return;
            m_subscriptions.erase(gone);
            QMetaObject::invokeMethod(this, &TelemetryHub::update, Qt::QueuedConnection);
        });
    }
    update();
    return true;
}

void TelemetryHub::unsubscribe(const QObject *subscriber)
{
    const auto known = std::find_if(
        m_subscriptions.begin(), m_subscriptions.end(),
        [subscriber](const Subscription &each) { return each.subscriber == subscriber; });
    if (known == m_subscriptions.end())
        return;
    m_subscriptions.erase(known);
    disconnect(subscriber, nullptr, this, nullptr);
    update();
}

bool TelemetryHub::isSubscribed(const QObject *subscriber) const
{
    return std::any_of(
        m_subscriptions.begin(), m_subscriptions.end(),
        [subscriber](const Subscription &each) { return each.subscriber == subscriber; });
}

void TelemetryHub::update()
{
    if (m_subscriptions.empty()) {
        stop();
        return;
    }
    TelemetryOptions options;
    options.rateHz = 0.0;
    bool asFastAsPossible = false;
    options.missesBeforeMissing = 1;
    for (const Subscription &subscription : m_subscriptions) {
        for (const ServoInfo &servo : subscription.servos) {
            const auto same = [&servo](const ServoInfo &s) {
                return sameServo(s, servo);
            };
            if (std::none_of(options.servos.begin(), options.servos.end(), same))
                options.servos.append(servo);
        }
        // 0 asks for as fast as the bus allows: nothing is faster.
        asFastAsPossible = asFastAsPossible || subscription.rateHz == 0.0;
        options.rateHz = std::max(options.rateHz, subscription.rateHz);
        options.missesBeforeMissing =
            std::max(options.missesBeforeMissing, subscription.missesBeforeMissing);
    }
    if (asFastAsPossible)
        options.rateHz = 0.0;
    if (m_streaming && sameServos(options.servos, m_options.servos)
        && options.rateHz == m_options.rateHz
        && options.missesBeforeMissing == m_options.missesBeforeMissing)
        return; // what streams already is what is asked
    options.stream = ++m_stream;
    m_options = options;
    m_client->runInSession([options](Session &s) { s.startTelemetry(options); });
    if (!m_streaming) {
        m_streaming = true;
        emit streamingChanged(true);
    }
}

void TelemetryHub::stop()
{
    ++m_stream;
    m_client->runInSession([](Session &s) { s.stopTelemetry(); });
    if (m_streaming) {
        m_streaming = false;
        emit streamingChanged(false);
    }
}

bool TelemetryHub::isStreamed(int index) const
{
    if (!m_streaming || index < 0 || index >= m_client->servos()->count())
        return false;
    const ServoInfo &info = m_client->servos()->at(index).info;
    return std::any_of(m_options.servos.begin(), m_options.servos.end(),
                       [&info](const ServoInfo &s) { return sameServo(s, info); });
}

std::optional<FeedbackSample> TelemetryHub::latestSample(int index) const
{
    if (index < 0 || index >= m_client->servos()->count())
        return std::nullopt;
    const ServoInfo &info = m_client->servos()->at(index).info;
    const auto sample = m_latest.constFind({info.id, info.baud});
    if (sample == m_latest.constEnd())
        return std::nullopt;
    return *sample;
}

void TelemetryHub::onSamples(const QVector<FeedbackSample> &samples, quint64 stream)
{
    if (!m_streaming || stream != m_stream)
        return; // the last batch of a stream already stopped or replaced
    for (const FeedbackSample &sample : samples)
        m_latest.insert({sample.id, sample.baud}, sample);
    emit samplesReceived(samples);
}

void TelemetryHub::onSharedSamples(const QVector<FeedbackSample> &samples)
{
    QVector<FeedbackSample> streamed;
    for (const FeedbackSample &sample : samples) {
        m_latest.insert({sample.id, sample.baud}, sample);
        const bool asked = m_streaming
            && std::any_of(m_options.servos.begin(), m_options.servos.end(),
                           [&sample](const ServoInfo &servo) {
                               return servo.address() == ServoAddress {sample.id, sample.baud};
                           });
        if (asked)
            streamed.append(sample);
    }
    if (!streamed.isEmpty())
        emit samplesReceived(streamed);
}

void TelemetryHub::onStats(const TelemetryStats &stats)
{
    if (stats.stream != m_stream)
        return; // a stream replaced or stopped since
    m_stats = stats;
    emit statsChanged(stats);
    if (!stats.running && m_streaming) { // stopped, or the link went down
        m_streaming = false;
        m_subscriptions.clear(); // what they asked for ended with it
        emit streamingChanged(false);
    }
}

} // namespace feetech
