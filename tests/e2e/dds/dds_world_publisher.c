// The DDS world's process (tests/e2e/dds/world.xml): publishes a WorldSample on the topic
// "rtf_world_samples" of the default domain every 10 ms (about 100 Hz) until SIGINT or
// SIGTERM, then exits 0. Each sample carries this world's token: the identity of the network
// namespace the publisher runs in (readlink /proc/self/ns/net), so that copies of one suite in
// private networks differ without an edited file; `dds_world_publisher TOKEN` publishes TOKEN
// instead (the end-to-end test's intruder). Prints "publishing TOKEN" once its writer exists:
// the world file's readiness check.
// The Cyclone DDS configuration comes from CYCLONEDDS_URI (set by the world file).
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include <dds/dds.h>

#include "world_sample.h"

static volatile sig_atomic_t stopping = 0;

static void on_stop(int signal_number) {
    (void)signal_number;
    stopping = 1;
}

static long long monotonic_ns(void) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (long long)now.tv_sec * 1000000000LL + now.tv_nsec;
}

static int failed(const char* what, dds_return_t code) {
    fprintf(stderr, "dds_world_publisher: %s: %s\n", what, dds_strretcode(code));
    return 1;
}

int main(int argc, char** argv) {
    char token[256];
    if (argc > 1) {
        snprintf(token, sizeof token, "%s", argv[1]);
    } else {
        ssize_t length = readlink("/proc/self/ns/net", token, sizeof token - 1);
        if (length < 0) {
            perror("dds_world_publisher: readlink /proc/self/ns/net");
            return 1;
        }
        token[length] = '\0';
    }
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_stop;
    sigaction(SIGINT, &action, NULL);
    sigaction(SIGTERM, &action, NULL);

    dds_entity_t participant = dds_create_participant(DDS_DOMAIN_DEFAULT, NULL, NULL);
    if (participant < 0)
        return failed("dds_create_participant", participant);
    dds_entity_t topic =
        dds_create_topic(participant, &rtf_dds_WorldSample_desc, "rtf_world_samples", NULL, NULL);
    if (topic < 0)
        return failed("dds_create_topic", topic);
    dds_qos_t* qos = dds_create_qos();
    dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
    dds_entity_t writer = dds_create_writer(participant, topic, qos, NULL);
    dds_delete_qos(qos);
    if (writer < 0)
        return failed("dds_create_writer", writer);
    printf("publishing %s\n", token);
    fflush(stdout);

    rtf_dds_WorldSample sample = {token, (long long)getpid(), 0, 0};
    while (!stopping) {
        sample.seq++;
        sample.sent_ns = monotonic_ns();
        dds_return_t written = dds_write(writer, &sample);
        if (written != DDS_RETCODE_OK)
            failed("dds_write", written);
        dds_sleepfor(DDS_MSECS(10));
    }
    dds_delete(participant);
    printf("stopped after %llu samples\n", (unsigned long long)sample.seq);
    return 0;
}
