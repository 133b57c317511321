#pragma once

#include "messages/Message.h"

#include <QObject>
#include <QTimer>

#include <chrono>
#include <functional>
#include <map>
#include <memory>
#include <optional>

namespace neptus::plans {

// Talks to one vehicle's plan engine over IMC: its plan database (PlanDB:
// store a plan, remove it, fetch it, ask for the database's state) and its
// plan control (PlanControl: start a stored plan, a plan given whole or one
// maneuver; stop; load; get the running plan). Every request carries a
// request id of its own and goes to the vehicle's own IMC id; it ends with
// the vehicle's SUCCESS or FAILURE (IN_PROGRESS keeps it waiting), or, after
// `attempts` sends `timeout` apart with no answer, as a failure saying so:
// never lost silently. Replies from other systems, to other requests or of
// another operation are not taken for it. A START ends with the vehicle's
// first answer ("plan loaded"): what DUNE says later under the same id is
// not an answer but the plan's progress, which PlanRuns follows from the
// vehicle's PlanControlState.
class PlanClient : public QObject
{
    Q_OBJECT

public:
    using Sender = std::function<void(const msg::Message &)>;

    struct Reply
    {
        quint16 requestId = 0;
        QString message;        // PlanDB or PlanControl
        QString op;             // SET, DEL, GET, GET_STATE, GET_DSTATE; START, STOP, LOAD, GET
        QString planId;
        bool ok = false;
        QString info;           // the vehicle's words, or why it failed here
        std::optional<msg::Message> arg; // PlanDB GET: the PlanSpecification; GET_STATE: the PlanDBState
        int attempts = 0;       // sends it took
    };

    PlanClient(std::shared_ptr<const msg::Schema> schema, quint16 vehicle, Sender send, QObject *parent = nullptr);

    quint16 vehicle() const { return m_vehicle; }
    void setTimeout(std::chrono::milliseconds timeout) { m_timeout = timeout; }
    void setAttempts(int attempts) { m_attempts = std::max(1, attempts); }

    // Each returns the request id its reply will carry.
    // PlanDB:
    quint16 set(const msg::Message &specification);
    quint16 remove(const QString &planId);
    quint16 get(const QString &planId);
    quint16 getState(bool detailed = false); // GET_DSTATE lists every plan with its MD5
    // PlanControl (`flags`: IMC's CALIBRATE 1, IGNORE_ERRORS 2):
    quint16 start(const QString &planId, quint16 flags = 0);
    quint16 start(const msg::Message &specificationOrManeuver, const QString &planId, quint16 flags = 0);
    quint16 stop(const QString &planId = {});
    quint16 load(const QString &planId);
    quint16 running(); // PlanControl GET

    // A message from the link. True when it was for this client.
    bool receive(const msg::Message &message);
    int pending() const { return static_cast<int>(m_pending.size()); }

signals:
    void replied(const neptus::plans::PlanClient::Reply &reply);

private:
    // A request's timer may end it from inside its own timeout: stopped and deleted later.
    struct StopLater
    {
        void operator()(QTimer *timer) const
        {
            timer->stop();
            timer->deleteLater();
        }
    };
    struct Request
    {
        msg::Message message;
        QString op;
        int attempts = 0;
        std::unique_ptr<QTimer, StopLater> timer;
    };

    quint16 request(const char *abbrev, const QString &op, const QString &planId, std::optional<msg::Message> arg,
                    quint16 flags = 0);
    void send(quint16 id);
    void finish(quint16 id, Reply reply);

    std::shared_ptr<const msg::Schema> m_schema;
    quint16 m_vehicle;
    Sender m_send;
    std::chrono::milliseconds m_timeout{3000};
    int m_attempts = 3;
    quint16 m_nextId = 1;
    std::map<quint16, Request> m_pending;
};

} // namespace neptus::plans
