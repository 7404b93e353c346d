flexrock_add_test(flexrock_model_tests SOURCES unit/body_test.cpp unit/impact_test.cpp LABEL unit)
flexrock_add_test(flexrock_integrate_tests SOURCES unit/dopri5_test.cpp LABEL unit)
flexrock_add_test(flexrock_rigid_validation_tests SOURCES validation/rigid_block_test.cpp LABEL validation)
