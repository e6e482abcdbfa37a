# char_body part: the Makefile reads the header dependencies (.d) of the library objects
# only, so a test object stayed stale when a header it includes changed (a char_body_t
# layout change then broke already-built suites at run time). Read the test objects' too.
-include $(wildcard $(BUILD)/*/obj/host_tests/*.d $(BUILD)/*/obj/host_tests/support/*.d)
