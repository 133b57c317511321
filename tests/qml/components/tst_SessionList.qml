import QtQuick
import QtTest
import Neptus.Components
import Neptus.Engine
import Neptus.Testing

// Issue #38: the operation's sessions from its database in the console, each
// opened for review in one tap (the program opens a review window: here the
// request is caught).
TestCase {
    id: test
    name: "SessionList"
    when: windowShown
    visible: true
    width: 760
    height: 520

    SessionList { id: list; width: 720; height: 480 }

    SignalSpy { id: opened; target: Fixtures.session.sessions; signalName: "openRequested" }

    function initTestCase() {
        Session.session = Fixtures.session
    }
    function cleanupTestCase() {
        Session.session = null
    }

    function test_1_listsEachSessionNewestFirstAndOpensOneInATap() {
        const dir = Fixtures.makeTempDir()
        const first = Fixtures.writeOperation(dir)
        verify(first !== "", "the database was written")
        list.refresh()
        tryCompare(list, "count", 3)
        tryVerify(() => !Fixtures.session.sessions.loading)
        const rows = Fixtures.session.sessions.rows
        compare(rows.get(0).console, "ops-c", "newest first")
        compare(rows.get(2).console, "ops-a")

        const a = findChild(list, "session-" + first)
        verify(a !== null)
        verify(findChild(a, "title").text.indexOf("ops-a  ·  deck") === 0, findChild(a, "title").text)
        compare(findChild(a, "systems").text, "lauv-sim-1")
        compare(findChild(a, "runs").text, "Plans: survey: completed")
        const review = findChild(a, "review")
        verify(review.enabled)
        verify(review.height >= Theme.touchTarget)
        mouseClick(review)
        compare(opened.count, 1, "one tap opens it")
        compare(opened.signalArguments[0][0], first)
        compare(opened.signalArguments[0][1], [dir + "/logs/a"])
        compare(findChild(list, "status").text, "Opening the session in a review window…")

        // A session whose logs are not on this machine says so and is not opened.
        const b = findChild(list, "session-" + rows.get(1).session)
        verify(b !== null)
        compare(findChild(b, "runs").text, "Plans: survey: running")
        const elsewhere = findChild(b, "review")
        verify(!elsewhere.enabled)
        compare(elsewhere.text, "No log here")
        mouseClick(elsewhere)
        // Nor is the console's own session.
        const c = findChild(list, "session-" + rows.get(0).session)
        compare(findChild(c, "review").text, "This console")
        verify(!findChild(c, "review").enabled)
        verify(!Fixtures.session.sessions.open(rows.get(0).session))
        compare(opened.count, 1)

        // A session that recorded nothing (ops-q) is folded away, one tap shows it.
        compare(Fixtures.session.sessions.quietCount, 1)
        const showQuiet = findChild(list, "showQuiet")
        verify(showQuiet !== null && showQuiet.visible)
        mouseClick(showQuiet)
        tryCompare(list, "count", 4)
        compare(rows.get(3).console, "ops-q")
        mouseClick(showQuiet)
        tryCompare(list, "count", 3)
    }

    function test_2_saysWhyWhenThereIsNoDatabase() {
        Fixtures.useDatabase("/nonexistent/operation.db")
        list.refresh()
        tryVerify(() => !Fixtures.session.sessions.loading)
        const status = findChild(list, "status")
        verify(status.visible)
        verify(status.text.indexOf("no database yet at /nonexistent/operation.db") === 0, status.text)
        compare(list.count, 0)
    }
}
