; ModuleID = '_drive'
source_filename = "<string>"
target datalayout = "e-m:e-p270:32:32-p271:32:32-p272:64:64-i64:64-i128:128-f80:128-n8:16:32:64-S128"
target triple = "x86_64-unknown-linux-gnu"

@.const.pickledata.1c6fb341d2c5b01f06081782f6c0835b91b257d2 = internal constant [1531 x i8] c"\80\04\95\F0\05\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94X\C8\05\00\00missing Environment: _ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE\94\85\94N\87\94."
@.const.pickledata.1c6fb341d2c5b01f06081782f6c0835b91b257d2.sha1 = internal constant [20 x i8] c"\1Co\B3A\D2\C5\B0\1F\06\08\17\82\F6\C0\83[\91\B2W\D2"
@.const.picklebuf.1c6fb341d2c5b01f06081782f6c0835b91b257d2 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.1c6fb341d2c5b01f06081782f6c0835b91b257d2, i32 1531, ptr @.const.pickledata.1c6fb341d2c5b01f06081782f6c0835b91b257d2.sha1, ptr null, i32 0 }
@.const.numba.experimental.function_type = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a = internal constant [495 x i8] c"\80\04\95\E4\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h\06h\09h\1Ah\0FN\87\94}\94(h\1Dh\06h\09h\0A\8C\07Integer\94\93\94h\0FN\87\94}\94(h\12\8C\05int64\94h\14K@\8C\06signed\94\88h\15K\1Au\87\94R\94h\1EK\01h\1Fh h\12\8C\13array(int64, 1d, C)\94h\15M\D9\01u\87\94R\94\87\94NNt\94b."
@.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.sha1 = internal constant [20 x i8] c"@\91\1F\92\B6X\A8y\02\93\02\91\E9K\9F\B5\1B(\A4\1A"
@.const.pickledata.4018623931e8e32c18b820afa637cf5cbf1f5535 = internal constant [195 x i8] c"\80\04\95\B8\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Ccfloat64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94K\A8\87\94\87\94."
@.const.pickledata.4018623931e8e32c18b820afa637cf5cbf1f5535.sha1 = internal constant [20 x i8] c"@\18b91\E8\E3,\18\B8 \AF\A67\CF\\\BF\1FU5"
@.const.picklebuf.4018623931e8e32c18b820afa637cf5cbf1f5535 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.4018623931e8e32c18b820afa637cf5cbf1f5535, i32 195, ptr @.const.pickledata.4018623931e8e32c18b820afa637cf5cbf1f5535.sha1, ptr null, i32 0 }
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const.pickledata.6412c1d038c4ddd627f0e96e9f665bdf17f85c41 = internal constant [197 x i8] c"\80\04\95\BA\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94K\C1\87\94\87\94."
@.const.pickledata.6412c1d038c4ddd627f0e96e9f665bdf17f85c41.sha1 = internal constant [20 x i8] c"d\12\C1\D08\C4\DD\D6'\F0\E9n\9Ff[\DF\17\F8\\A"
@.const.picklebuf.6412c1d038c4ddd627f0e96e9f665bdf17f85c41 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.6412c1d038c4ddd627f0e96e9f665bdf17f85c41, i32 197, ptr @.const.pickledata.6412c1d038c4ddd627f0e96e9f665bdf17f85c41.sha1, ptr null, i32 0 }
@.const.pickledata.f1e7bd29a4ad75134f039f453b107cce992df92e = internal constant [197 x i8] c"\80\04\95\BA\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94K\C6\87\94\87\94."
@.const.pickledata.f1e7bd29a4ad75134f039f453b107cce992df92e.sha1 = internal constant [20 x i8] c"\F1\E7\BD)\A4\ADu\13O\03\9FE;\10|\CE\99-\F9."
@.const.picklebuf.f1e7bd29a4ad75134f039f453b107cce992df92e = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.f1e7bd29a4ad75134f039f453b107cce992df92e, i32 197, ptr @.const.pickledata.f1e7bd29a4ad75134f039f453b107cce992df92e.sha1, ptr null, i32 0 }
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366 = internal constant [69 x i8] c"\80\04\95:\00\00\00\00\00\00\00\8C\08builtins\94\8C\11ZeroDivisionError\94\93\94\8C\10division by zero\94\85\94N\87\94."
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1 = internal constant [20 x i8] c"\B2\80\08\A0\F8\8B\AD_\F0\F0$>\84\DA\B9\0C\AB\19\B3f"
@.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366, i32 69, ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1, ptr null, i32 0 }
@.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908 = internal constant [498 x i8] c"\80\04\95\E7\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94(h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h\06h\09h\1Ah\0FN\87\94}\94(h\1Dh\06h\09h\0A\8C\07Integer\94\93\94h\0FN\87\94}\94(h\12\8C\05int64\94h\14K@\8C\06signed\94\88h\15K\1Au\87\94R\94h\1EK\01h\1Fh h\12\8C\13array(int64, 1d, C)\94h\15M\D9\01u\87\94R\94h#t\94NNt\94b."
@.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1 = internal constant [20 x i8] c"k\A8\E0\C0\FE\83@\E8D\97<\04^\ED\C9\A1\91\14\E9\08"
@.const.pickledata.91aaf861f3f5a4f952b411fb74b5ebbdc030024d = internal constant [218 x i8] c"\80\04\95\CF\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Czfloat64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94K\F9\87\94\87\94."
@.const.pickledata.91aaf861f3f5a4f952b411fb74b5ebbdc030024d.sha1 = internal constant [20 x i8] c"\91\AA\F8a\F3\F5\A4\F9R\B4\11\FBt\B5\EB\BD\C00\02M"
@.const.picklebuf.91aaf861f3f5a4f952b411fb74b5ebbdc030024d = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.91aaf861f3f5a4f952b411fb74b5ebbdc030024d, i32 218, ptr @.const.pickledata.91aaf861f3f5a4f952b411fb74b5ebbdc030024d.sha1, ptr null, i32 0 }
@.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091 = internal constant [560 x i8] c"\80\04\95%\02\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\07Integer\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\05int64\94\8C\08bitwidth\94K@\8C\06signed\94\88\8C\05_code\94K\1Au\87\94R\94(h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\06h\09h\0A\8C\05Float\94\93\94h\0FN\87\94}\94(h\12\8C\07float64\94h\14K@h\16K\1Cu\87\94R\94\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\16M\C4\01u\87\94R\94h+h\06h\09h\1Bh\0FN\87\94}\94(h\1Eh\18h&K\01h'h(h\12\8C\13array(int64, 1d, C)\94h\16M\D9\01u\87\94R\94h%h\06h\09h\1Bh\0FN\87\94}\94(h\1Eh%h&K\02h'h(h\12\8C\15array(float64, 2d, C)\94h\16M\DA\01u\87\94R\94t\94NNt\94b."
@.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.sha1 = internal constant [20 x i8] c"\1C\82\C2A>\F0\A1\AF\B9r\9Ep\9F\89_^\8D\E5\D0\91"
@.const.pickledata.b1f499986692c125c12fdde1e97e44c2fd7327d1 = internal constant [226 x i8] c"\80\04\95\D7\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8C\81int64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), float64, array(float64, 2d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94M\09\01\87\94\87\94."
@.const.pickledata.b1f499986692c125c12fdde1e97e44c2fd7327d1.sha1 = internal constant [20 x i8] c"\B1\F4\99\98f\92\C1%\C1/\DD\E1\E9~D\C2\FDs'\D1"
@.const.picklebuf.b1f499986692c125c12fdde1e97e44c2fd7327d1 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.b1f499986692c125c12fdde1e97e44c2fd7327d1, i32 226, ptr @.const.pickledata.b1f499986692c125c12fdde1e97e44c2fd7327d1.sha1, ptr null, i32 0 }
@.const.pickledata.3ca9c262f616dc09ad7b0c2d49d13087359018c0 = internal constant [219 x i8] c"\80\04\95\D0\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Czfloat64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94M\13\01\87\94\87\94."
@.const.pickledata.3ca9c262f616dc09ad7b0c2d49d13087359018c0.sha1 = internal constant [20 x i8] c"<\A9\C2b\F6\16\DC\09\AD{\0C-I\D10\875\90\18\C0"
@.const.picklebuf.3ca9c262f616dc09ad7b0c2d49d13087359018c0 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.3ca9c262f616dc09ad7b0c2d49d13087359018c0, i32 219, ptr @.const.pickledata.3ca9c262f616dc09ad7b0c2d49d13087359018c0.sha1, ptr null, i32 0 }
@.const.pickledata.4bd459b058f64e017c239a70098f62534352b29d = internal constant [219 x i8] c"\80\04\95\D0\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Czfloat64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94M\18\01\87\94\87\94."
@.const.pickledata.4bd459b058f64e017c239a70098f62534352b29d.sha1 = internal constant [20 x i8] c"K\D4Y\B0X\F6N\01|#\9Ap\09\8FbSCR\B2\9D"
@.const.picklebuf.4bd459b058f64e017c239a70098f62534352b29d = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.4bd459b058f64e017c239a70098f62534352b29d, i32 219, ptr @.const.pickledata.4bd459b058f64e017c239a70098f62534352b29d.sha1, ptr null, i32 0 }
@.const.pickledata.d164b050fccb0b900982ad985a7025ea41290c6a = internal constant [219 x i8] c"\80\04\95\D0\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Czfloat64(array(float64, 1d, C), array(float64, 1d, C), array(int64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_drive\94\8C!/work/main/charts/solvers/loop.py\94M\1B\01\87\94\87\94."
@.const.pickledata.d164b050fccb0b900982ad985a7025ea41290c6a.sha1 = internal constant [20 x i8] c"\D1d\B0P\FC\CB\0B\90\09\82\AD\98Zp%\EAA)\0Cj"
@.const.picklebuf.d164b050fccb0b900982ad985a7025ea41290c6a = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.d164b050fccb0b900982ad985a7025ea41290c6a, i32 219, ptr @.const.pickledata.d164b050fccb0b900982ad985a7025ea41290c6a.sha1, ptr null, i32 0 }
@.const._drive = internal constant [7 x i8] c"_drive\00"
@_ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@".const.missing Environment: _ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE" = internal constant [1481 x i8] c"missing Environment: _ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE\00"
@.const.numba.experimental.function_type.1 = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address.2 = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.3 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.4 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const._get_jit_address = internal constant [17 x i8] c"_get_jit_address\00"
@.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.5 = internal constant [495 x i8] c"\80\04\95\E4\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h\06h\09h\1Ah\0FN\87\94}\94(h\1Dh\06h\09h\0A\8C\07Integer\94\93\94h\0FN\87\94}\94(h\12\8C\05int64\94h\14K@\8C\06signed\94\88h\15K\1Au\87\94R\94h\1EK\01h\1Fh h\12\8C\13array(int64, 1d, C)\94h\15M\D9\01u\87\94R\94\87\94NNt\94b."
@.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.sha1.6 = internal constant [20 x i8] c"@\91\1F\92\B6X\A8y\02\93\02\91\E9K\9F\B5\1B(\A4\1A"
@.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.7 = internal constant [560 x i8] c"\80\04\95%\02\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\07Integer\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\05int64\94\8C\08bitwidth\94K@\8C\06signed\94\88\8C\05_code\94K\1Au\87\94R\94(h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\06h\09h\0A\8C\05Float\94\93\94h\0FN\87\94}\94(h\12\8C\07float64\94h\14K@h\16K\1Cu\87\94R\94\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\16M\C4\01u\87\94R\94h+h\06h\09h\1Bh\0FN\87\94}\94(h\1Eh\18h&K\01h'h(h\12\8C\13array(int64, 1d, C)\94h\16M\D9\01u\87\94R\94h%h\06h\09h\1Bh\0FN\87\94}\94(h\1Eh%h&K\02h'h(h\12\8C\15array(float64, 2d, C)\94h\16M\DA\01u\87\94R\94t\94NNt\94b."
@.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.sha1.8 = internal constant [20 x i8] c"\1C\82\C2A>\F0\A1\AF\B9r\9Ep\9F\89_^\8D\E5\D0\91"
@.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.9 = internal constant [498 x i8] c"\80\04\95\E7\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94(h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h\06h\09h\1Ah\0FN\87\94}\94(h\1Dh\06h\09h\0A\8C\07Integer\94\93\94h\0FN\87\94}\94(h\12\8C\05int64\94h\14K@\8C\06signed\94\88h\15K\1Au\87\94R\94h\1EK\01h\1Fh h\12\8C\13array(int64, 1d, C)\94h\15M\D9\01u\87\94R\94h#t\94NNt\94b."
@.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1.10 = internal constant [20 x i8] c"k\A8\E0\C0\FE\83@\E8D\97<\04^\ED\C9\A1\91\14\E9\08"
@".const.can't unbox array from PyObject into native value.  The object maybe of a different type" = internal constant [89 x i8] c"can't unbox array from PyObject into native value.  The object maybe of a different type\00"
@".const.Error creating Python tuple from runtime exception arguments" = internal constant [61 x i8] c"Error creating Python tuple from runtime exception arguments\00"
@".const.unknown error when calling native function" = internal constant [43 x i8] c"unknown error when calling native function\00"
@".const.Error creating Python tuple from runtime exception arguments.11" = internal constant [61 x i8] c"Error creating Python tuple from runtime exception arguments\00"
@".const.unknown error when calling native function.12" = internal constant [43 x i8] c"unknown error when calling native function\00"
@".const.<numba.core.cpu.CPUContext>" = internal constant [28 x i8] c"<numba.core.cpu.CPUContext>\00"
@.const.pickledata.dc3bba832c4c3758273d0db24b835691af3f316c = internal constant [83 x i8] c"\80\04\95H\00\00\00\00\00\00\00\8C\08builtins\94\8C\13NotImplementedError\94\93\94\8C\1Cincompatible shape for array\94\85\94N\87\94."
@.const.pickledata.dc3bba832c4c3758273d0db24b835691af3f316c.sha1 = internal constant [20 x i8] c"\DC;\BA\83,L7X'=\0D\B2K\83V\91\AF?1l"
@.const.picklebuf.dc3bba832c4c3758273d0db24b835691af3f316c = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.dc3bba832c4c3758273d0db24b835691af3f316c, i32 83, ptr @.const.pickledata.dc3bba832c4c3758273d0db24b835691af3f316c.sha1, ptr null, i32 0 }
@.const.pickledata.f52a4d7919abe2cf3e7519de076bcff016108bed = internal constant [462 x i8] c"\80\04\95\C3\01\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94X\9B\01\00\00missing Environment: _ZN08NumbaEnv6charts7solvers2rk8rk4_stepB3v74B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMVC_2fAwA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE\94\85\94N\87\94."
@.const.pickledata.f52a4d7919abe2cf3e7519de076bcff016108bed.sha1 = internal constant [20 x i8] c"\F5*My\19\AB\E2\CF>u\19\DE\07k\CF\F0\16\10\8B\ED"
@.const.picklebuf.f52a4d7919abe2cf3e7519de076bcff016108bed = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.f52a4d7919abe2cf3e7519de076bcff016108bed, i32 462, ptr @.const.pickledata.f52a4d7919abe2cf3e7519de076bcff016108bed.sha1, ptr null, i32 0 }
@.const.numba.experimental.function_type.17 = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address.18 = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.19 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.20 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const.pickledata.32c8b183712bee87dcda2e43a3f74916a0d4de74 = internal constant [197 x i8] c"\80\04\95\BA\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\08rk4_step\94\8C\1F/work/main/charts/solvers/rk.py\94K}\87\94\87\94."
@.const.pickledata.32c8b183712bee87dcda2e43a3f74916a0d4de74.sha1 = internal constant [20 x i8] c"2\C8\B1\83q+\EE\87\DC\DA.C\A3\F7I\16\A0\D4\DEt"
@.const.picklebuf.32c8b183712bee87dcda2e43a3f74916a0d4de74 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.32c8b183712bee87dcda2e43a3f74916a0d4de74, i32 197, ptr @.const.pickledata.32c8b183712bee87dcda2e43a3f74916a0d4de74.sha1, ptr null, i32 0 }
@.const.pickledata.772380b16aa618530594268027b0fd5294b03a2b = internal constant [197 x i8] c"\80\04\95\BA\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\08rk4_step\94\8C\1F/work/main/charts/solvers/rk.py\94K\80\87\94\87\94."
@.const.pickledata.772380b16aa618530594268027b0fd5294b03a2b.sha1 = internal constant [20 x i8] c"w#\80\B1j\A6\18S\05\94&\80'\B0\FDR\94\B0:+"
@.const.picklebuf.772380b16aa618530594268027b0fd5294b03a2b = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.772380b16aa618530594268027b0fd5294b03a2b, i32 197, ptr @.const.pickledata.772380b16aa618530594268027b0fd5294b03a2b.sha1, ptr null, i32 0 }
@_ZN08NumbaEnv6charts7solvers2rk8rk4_stepB3v74B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMVC_2fAwA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv5numba2np8arrayobj23normalize_reshape_valueB3v81B40c8tJTC_2fWQA93W1AaAIYBPIqRBFCjDSyhCQA_3dEy5ArrayIxLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv5numba7cpython8builtins6ol_min12_3clocals_3e4implB3v80B38c8tJTIeFIjxB2IKSgI4CrvQClcaMQ7CEJgA_3dE15StarArgUniTupleIdLi2EE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv6charts7solvers2rk13hermite_denseB3v82B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.34 = internal constant [69 x i8] c"\80\04\95:\00\00\00\00\00\00\00\8C\08builtins\94\8C\11ZeroDivisionError\94\93\94\8C\10division by zero\94\85\94N\87\94."
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.35 = internal constant [20 x i8] c"\B2\80\08\A0\F8\8B\AD_\F0\F0$>\84\DA\B9\0C\AB\19\B3f"
@.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.34, i32 69, ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.35, ptr null, i32 0 }
@.const.pickledata.c3243e19d8c377ae31c00ff41e00cb6ab90277f0 = internal constant [468 x i8] c"\80\04\95\C9\01\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94X\A1\01\00\00missing Environment: _ZN08NumbaEnv6charts7solvers2rk12initial_stepB3v84B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdddd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE\94\85\94N\87\94."
@.const.pickledata.c3243e19d8c377ae31c00ff41e00cb6ab90277f0.sha1 = internal constant [20 x i8] c"\C3$>\19\D8\C3w\AE1\C0\0F\F4\1E\00\CBj\B9\02w\F0"
@.const.picklebuf.c3243e19d8c377ae31c00ff41e00cb6ab90277f0 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.c3243e19d8c377ae31c00ff41e00cb6ab90277f0, i32 468, ptr @.const.pickledata.c3243e19d8c377ae31c00ff41e00cb6ab90277f0.sha1, ptr null, i32 0 }
@.const.numba.experimental.function_type.30 = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address.31 = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.32 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.33 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const.pickledata.4e3d529372d5f63b747cb9250801d0e712742805 = internal constant [202 x i8] c"\80\04\95\BF\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\0Cinitial_step\94\8C\1F/work/main/charts/solvers/rk.py\94M\0E\01\87\94\87\94."
@.const.pickledata.4e3d529372d5f63b747cb9250801d0e712742805.sha1 = internal constant [20 x i8] c"N=R\93r\D5\F6;t|\B9%\08\01\D0\E7\12t(\05"
@.const.picklebuf.4e3d529372d5f63b747cb9250801d0e712742805 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.4e3d529372d5f63b747cb9250801d0e712742805, i32 202, ptr @.const.pickledata.4e3d529372d5f63b747cb9250801d0e712742805.sha1, ptr null, i32 0 }
@_ZN08NumbaEnv6charts7solvers2rk12initial_stepB3v84B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdddd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv5numba7cpython8builtins6ol_min12_3clocals_3e4implB3v85B42c8tJTIeFIjxB2IKSgI4CrvQClcaMQ5hEEUSJJgA_3dE15StarArgUniTupleIdLi3EE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv5numba7cpython8builtins6ol_min12_3clocals_3e4implB3v87B42c8tJTIeFIjxB2IKSgI4CrvQClcaMQ5hEEUSJJgA_3dE15StarArgUniTupleIdLi4EE = common local_unnamed_addr global ptr null
@.const.pickledata.f77baf611f08f85307c33ca008225eb68c830d48 = internal constant [466 x i8] c"\80\04\95\C7\01\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94X\9F\01\00\00missing Environment: _ZN08NumbaEnv6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd\94\85\94N\87\94."
@.const.pickledata.f77baf611f08f85307c33ca008225eb68c830d48.sha1 = internal constant [20 x i8] c"\F7{\AFa\1F\08\F8S\07\C3<\A0\08\22^\B6\8C\83\0DH"
@.const.picklebuf.f77baf611f08f85307c33ca008225eb68c830d48 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.f77baf611f08f85307c33ca008225eb68c830d48, i32 466, ptr @.const.pickledata.f77baf611f08f85307c33ca008225eb68c830d48.sha1, ptr null, i32 0 }
@.const.numba.experimental.function_type.38 = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address.39 = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.40 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.41 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const.pickledata.2618a0875071fc91168fe680494fc2bbf1957ea8 = internal constant [200 x i8] c"\80\04\95\BD\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\0Bdop853_step\94\8C\1F/work/main/charts/solvers/rk.py\94K\A3\87\94\87\94."
@.const.pickledata.2618a0875071fc91168fe680494fc2bbf1957ea8.sha1 = internal constant [20 x i8] c"&\18\A0\87Pq\FC\91\16\8F\E6\80IO\C2\BB\F1\95~\A8"
@.const.picklebuf.2618a0875071fc91168fe680494fc2bbf1957ea8 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.2618a0875071fc91168fe680494fc2bbf1957ea8, i32 200, ptr @.const.pickledata.2618a0875071fc91168fe680494fc2bbf1957ea8.sha1, ptr null, i32 0 }
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.43 = internal constant [69 x i8] c"\80\04\95:\00\00\00\00\00\00\00\8C\08builtins\94\8C\11ZeroDivisionError\94\93\94\8C\10division by zero\94\85\94N\87\94."
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.44 = internal constant [20 x i8] c"\B2\80\08\A0\F8\8B\AD_\F0\F0$>\84\DA\B9\0C\AB\19\B3f"
@.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.42 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.43, i32 69, ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.44, ptr null, i32 0 }
@_ZN08NumbaEnv6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd = common local_unnamed_addr global ptr null
@.const.array.data = internal unnamed_addr constant [2048 x i8] c"\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00:\E6\DA8h\EE\AA?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\AC,\A4*\CE2\94?\02C\F6?5L\AE?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\02C\F6?5L\9E?\00\00\00\00\00\00\00\00A\B2\F8\EF'\B9\B6?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\FA\E9\CD~\0D\E5\CE?\00\00\00\00\00\00\00\00\07\15\AD\B5:N\EC\BF\F5\9E\C7z=\98\ED?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00h/\A1\BD\84\F6\A2?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\006m\DB;\B6\DD\C5?\9A\F1f?S\0F\C0?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\A3?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\EDG3\0F\D3\CA\C5?M\E02\C3\B3\D4\AE?\00\00\00\00\00\00\92\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\92\87\E7\FE\B8\FD\A2?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00r]Y\F6#\CF\C5?\98\A6\DE@\86u\BB?/\D3\FC \CC_\8F\BFq\0B\FB.\D9\F1\80?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\13X\98\8B\B7\F8\E3?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\8A\BC\C6\AC\1B\E3\0A\C0\F9\11\8E\F0s\C8\EB\BFU\18\8D\D8\93\97;@i\AD\92\F8p'4@\F9B\\\86\B4\BEE\C0\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00U\B6!\E3\05\92\DE?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\7F\D2K\A3\A8\E7\03\C0\C8\93\8C\96\A9\E3\E2\BF\EEU\D6\A6\E4:5@\B8X\F2\B5\F7\8E.@\B9\11\D7\18\E4\A4@\C0v\A8\B4\D9\B3\D1\94\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\9B9\1D\1F\12\FD\ED\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\9D\0B\FBi\D8\BE\14@\A9.y\02\87v\F1?\1C\0C\11\E2\B0L \C0\A8u\E9\05#\852\C0:\86\CB\06O\BD6@\9D\10\CFw\E7\F2\03@,W+\0D\C6_\08\C0\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\DC\FC\09;\BD/\02@\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00U\FE\CAc\A9\11%\C0\ACr\AC5\C9\01\00\C0\060\FF\8E|\F51\C0\01\8A\B5\18\EA\F2;@\13\EC\1C}:\DF\06\C0\A93\9F\1A\E7\BE!\C0a\18\C8B\9C\B8(@\02\E2Sb\AC\96\E4?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00|\17\D1hc\CC\AB?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\E2Z\AD\D2\1E\CD\11@\9F\AB\D5E\A8C\FE?C\AF\96\CFn4\17\C0\98\EB\F0\F2\1D\EA\D3?\02\B0C\8F\02z\C3\BF-\E7\7FiW\C6\C9?\C2k\ABPO\E4\A6?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00H\B1\CE\A2\FC\C1\AC?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\B85\1A\F2X9\D0?>\C2w\C2\C2\84\CF\BF\EF\9D\\U\02\CB\BF\BF\13\19-\CE\10\9F\C3?,e8\9B\B6\CB\80?\A9k9\0F\84\FF~?0H\FA\B4\8A\FE\80\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00c\DB{\89\A1L\A0?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00E\9F\F5\E5\E9\FA\9C?\F9\8C|\01\DBi\AB?i\94\C6/\F7\1E\AC\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00S\E1\F6\EE\10g\1C\BF #\D3Rz\129?\9B\14\E7\13\0EP6\BF\89\D9\0C\B2\86\16\C2?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\15`+y\09s\DB\BF\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\9A\DC\AFD]\CA\12\C0\A3\ED\19\C4\D2\BB\1E@\1C\17WD\A5F\10@D\BA\EDD\9E\D4\D6?\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\00\D4qH\C2\EE\EBV\BF\96\19?\A2\82\94\07@\22\22\CAmJM\22\C0\00\00\00\00\00\00\00\00", align 8
@.const.pickledata.4004c2ff75c85dd682fe6bf6d34405e3be8f361c = internal constant [428 x i8] c"\80\04\95\A1\01\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94Xy\01\00\00missing Environment: _ZN08NumbaEnv6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE\94\85\94N\87\94."
@.const.pickledata.4004c2ff75c85dd682fe6bf6d34405e3be8f361c.sha1 = internal constant [20 x i8] c"@\04\C2\FFu\C8]\D6\82\FEk\F6\D3D\05\E3\BE\8F6\1C"
@.const.picklebuf.4004c2ff75c85dd682fe6bf6d34405e3be8f361c = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.4004c2ff75c85dd682fe6bf6d34405e3be8f361c, i32 428, ptr @.const.pickledata.4004c2ff75c85dd682fe6bf6d34405e3be8f361c.sha1, ptr null, i32 0 }
@.const.numba.experimental.function_type.13 = internal constant [33 x i8] c"numba.experimental.function_type\00"
@.const._get_wrapper_address.14 = internal constant [21 x i8] c"_get_wrapper_address\00"
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.15 = internal constant [380 x i8] c"\80\04\95q\01\00\00\00\00\00\00\8C\1Bnumba.core.typing.templates\94\8C\09Signature\94\93\94)\81\94(\8C\19numba.core.types.abstract\94\8C\13_type_reconstructor\94\93\94\8C\07copyreg\94\8C\0E_reconstructor\94\93\94\8C\18numba.core.types.scalars\94\8C\05Float\94\93\94\8C\08builtins\94\8C\06object\94\93\94N\87\94}\94(\8C\04name\94\8C\07float64\94\8C\08bitwidth\94K@\8C\05_code\94K\1Cu\87\94R\94h\06h\09\8C\19numba.core.types.npytypes\94\8C\05Array\94\93\94h\0FN\87\94}\94(\8C\05dtype\94h\17\8C\04ndim\94K\01\8C\06layout\94\8C\01C\94h\12\8C\15array(float64, 1d, C)\94h\15M\C4\01u\87\94R\94h#h#\87\94NNt\94b."
@.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.16 = internal constant [20 x i8] c"\0DP:\D5\16\DF;N\9Fw\F9Q\FB\0C\A3T6\FE\A2\F4"
@.const.pickledata.51fac48a62be4cbf2f5a4837d75a1cd17a138c25 = internal constant [195 x i8] c"\80\04\95\B8\00\00\00\00\00\00\00\8C\08builtins\94\8C\0CRuntimeError\94\93\94\8Cefloat64(array(float64, 1d, C), array(float64, 1d, C), array(float64, 1d, C)) function address is null\94\85\94\8C\06_stage\94\8C\1F/work/main/charts/solvers/rk.py\94K\8F\87\94\87\94."
@.const.pickledata.51fac48a62be4cbf2f5a4837d75a1cd17a138c25.sha1 = internal constant [20 x i8] c"Q\FA\C4\8Ab\BEL\BF/ZH7\D7Z\1C\D1z\13\8C%"
@.const.picklebuf.51fac48a62be4cbf2f5a4837d75a1cd17a138c25 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.51fac48a62be4cbf2f5a4837d75a1cd17a138c25, i32 195, ptr @.const.pickledata.51fac48a62be4cbf2f5a4837d75a1cd17a138c25.sha1, ptr null, i32 0 }
@_ZN08NumbaEnv5numba7cpython7numbers14int_power_impl12_3clocals_3e9int_powerB3v88B42c8tJTC_2fWQA93W1AaAIYBPIqRBFCjDSZRVAJmaQIAEdx = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv6charts7solvers2rk11step_factorB3v91B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dEdb = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv5numba7cpython8builtins6ol_min12_3clocals_3e4implB3v73B42c8tJTIeFIjxB2IKSgI4CrvQClcaMQ5hEEUSJJgA_3dE15StarArgUniTupleIdLi2EE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv6charts7solvers2rk12dop853_denseB3v92B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@PyExc_StopIteration = external global i8
@PyExc_SystemError = external global i8
@_ZN08NumbaEnv6charts7solvers2rk10dense_evalB3v94B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@_ZN08NumbaEnv6charts7solvers4loop15_record_segmentB3v95B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedEdd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.56 = internal constant [69 x i8] c"\80\04\95:\00\00\00\00\00\00\00\8C\08builtins\94\8C\11ZeroDivisionError\94\93\94\8C\10division by zero\94\85\94N\87\94."
@.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.57 = internal constant [20 x i8] c"\B2\80\08\A0\F8\8B\AD_\F0\F0$>\84\DA\B9\0C\AB\19\B3f"
@.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.55 = internal constant { ptr, i32, ptr, ptr, i32 } { ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.56, i32 69, ptr @.const.pickledata.b28008a0f88bad5ff0f0243e84dab90cab19b366.sha1.57, ptr null, i32 0 }
@_ZN08NumbaEnv6charts7solvers4loop7monitorB3v96B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE = common local_unnamed_addr global ptr null
@PyExc_TypeError = external global i8
@PyExc_RuntimeError = external global i8
@_ZN08NumbaEnv5numba7cpython8builtins6ol_max12_3clocals_3e4implB3v86B42c8tJTIeFIjxB2IKSgI4CrvQClcaMQ5hEEUSJJgA_3dE15StarArgUniTupleIdLi2EE = common local_unnamed_addr global ptr null

define range(i32 -1, -2) i32 @_ZN6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.rhs.0, ptr %arg.rhs.1, ptr readonly captures(address_is_null) %arg.rhs.2, ptr readonly captures(address_is_null) %arg.cap.0, ptr %arg.cap.1, ptr readonly captures(address_is_null) %arg.cap.2, ptr readonly captures(address_is_null) %arg.post.0, ptr %arg.post.1, ptr readonly captures(address_is_null) %arg.post.2, ptr readonly captures(address_is_null) %arg.to_ambient.0, ptr %arg.to_ambient.1, ptr readonly captures(address_is_null) %arg.to_ambient.2, ptr readonly captures(address_is_null) %arg.invariants.0, ptr %arg.invariants.1, ptr readonly captures(address_is_null) %arg.invariants.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, ptr %arg.st.0, ptr readnone captures(none) %arg.st.1, i64 %arg.st.2, i64 %arg.st.3, ptr captures(none) %arg.st.4, i64 %arg.st.5.0, i64 %arg.st.6.0, ptr %arg.ist.0, ptr readnone captures(none) %arg.ist.1, i64 %arg.ist.2, i64 %arg.ist.3, ptr captures(none) %arg.ist.4, i64 %arg.ist.5.0, i64 %arg.ist.6.0, ptr %arg.t_eval.0, ptr readnone captures(none) %arg.t_eval.1, i64 %arg.t_eval.2, i64 %arg.t_eval.3, ptr readonly captures(none) %arg.t_eval.4, i64 %arg.t_eval.5.0, i64 %arg.t_eval.6.0, ptr %arg.T_out.0, ptr readnone captures(none) %arg.T_out.1, i64 %arg.T_out.2, i64 %arg.T_out.3, ptr writeonly captures(none) %arg.T_out.4, i64 %arg.T_out.5.0, i64 %arg.T_out.6.0, ptr %arg.Y_out.0, ptr %arg.Y_out.1, i64 %arg.Y_out.2, i64 %arg.Y_out.3, ptr %arg.Y_out.4, i64 %arg.Y_out.5.0, i64 %arg.Y_out.5.1, i64 %arg.Y_out.6.0, i64 %arg.Y_out.6.1, ptr %arg.log.0, ptr %arg.log.1, i64 %arg.log.2, i64 %arg.log.3, ptr %arg.log.4, i64 %arg.log.5.0, i64 %arg.log.5.1, i64 %arg.log.6.0, i64 %arg.log.6.1, ptr %arg.mon.0, ptr readnone captures(none) %arg.mon.1, i64 %arg.mon.2, i64 %arg.mon.3, ptr captures(none) %arg.mon.4, i64 %arg.mon.5.0, i64 %arg.mon.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.F.0, ptr readnone captures(none) %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr captures(none) %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, ptr %arg.inv.0, ptr %arg.inv.1, i64 %arg.inv.2, i64 %arg.inv.3, ptr %arg.inv.4, i64 %arg.inv.5.0, i64 %arg.inv.6.0, ptr %arg.Seg.0, ptr readnone captures(none) %arg.Seg.1, i64 %arg.Seg.2, i64 %arg.Seg.3, ptr writeonly captures(none) %arg.Seg.4, i64 %arg.Seg.5.0, i64 %arg.Seg.5.1, i64 %arg.Seg.6.0, i64 %arg.Seg.6.1, ptr %arg.ISeg.0, ptr readnone captures(none) %arg.ISeg.1, i64 %arg.ISeg.2, i64 %arg.ISeg.3, ptr writeonly captures(none) %arg.ISeg.4, i64 %arg.ISeg.5.0, i64 %arg.ISeg.5.1, i64 %arg.ISeg.6.0, i64 %arg.ISeg.6.1) local_unnamed_addr {
B0:
  %const = bitcast i64 9223372036854775776 to i64
  %arg.ynew.4755 = ptrtoint ptr %arg.ynew.4 to i64
  %arg.y.4754 = ptrtoint ptr %arg.y.4 to i64
  %.1294 = alloca i32, align 4
  store i32 0, ptr %.1294, align 4
  %.1329 = alloca double, align 8
  store double 0.000000e+00, ptr %.1329, align 8
  %excinfo.1 = alloca ptr, align 8
  store ptr null, ptr %excinfo.1, align 8
  %.1775 = alloca double, align 8
  store double 0.000000e+00, ptr %.1775, align 8
  %excinfo.4 = alloca ptr, align 8
  store ptr null, ptr %excinfo.4, align 8
  %.2238 = alloca i32, align 4
  store i32 0, ptr %.2238, align 4
  %.2273 = alloca double, align 8
  store double 0.000000e+00, ptr %.2273, align 8
  %excinfo.5 = alloca ptr, align 8
  store ptr null, ptr %excinfo.5, align 8
  %.2517 = alloca ptr, align 8
  store ptr null, ptr %.2517, align 8
  %excinfo.6 = alloca ptr, align 8
  store ptr null, ptr %excinfo.6, align 8
  %.2707 = alloca i32, align 4
  store i32 0, ptr %.2707, align 4
  %.2742 = alloca double, align 8
  store double 0.000000e+00, ptr %.2742, align 8
  %excinfo.7 = alloca ptr, align 8
  store ptr null, ptr %excinfo.7, align 8
  %.3291 = alloca double, align 8
  store double 0.000000e+00, ptr %.3291, align 8
  %excinfo.8 = alloca ptr, align 8
  store ptr null, ptr %excinfo.8, align 8
  %.3622 = alloca [2 x double], align 8
  %excinfo.10 = alloca ptr, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(16) %.3622, i8 0, i64 16, i1 false)
  store ptr null, ptr %excinfo.10, align 8
  %.4306 = alloca ptr, align 8
  store ptr null, ptr %.4306, align 8
  %excinfo.12 = alloca ptr, align 8
  store ptr null, ptr %excinfo.12, align 8
  %.4734 = alloca ptr, align 8
  store ptr null, ptr %.4734, align 8
  %excinfo.13 = alloca ptr, align 8
  store ptr null, ptr %excinfo.13, align 8
  %.4885 = alloca i32, align 4
  store i32 0, ptr %.4885, align 4
  %.4920 = alloca double, align 8
  store double 0.000000e+00, ptr %.4920, align 8
  %excinfo.14 = alloca ptr, align 8
  store ptr null, ptr %excinfo.14, align 8
  %.5471 = alloca ptr, align 8
  store ptr null, ptr %.5471, align 8
  %excinfo.15 = alloca ptr, align 8
  store ptr null, ptr %excinfo.15, align 8
  %.6090 = alloca i32, align 4
  store i32 0, ptr %.6090, align 4
  %.6125 = alloca i64, align 8
  store i64 0, ptr %.6125, align 8
  %excinfo.16 = alloca ptr, align 8
  store ptr null, ptr %excinfo.16, align 8
  %.6556 = alloca i32, align 4
  store i32 0, ptr %.6556, align 4
  %.6591 = alloca double, align 8
  store double 0.000000e+00, ptr %.6591, align 8
  %excinfo.17 = alloca ptr, align 8
  store ptr null, ptr %excinfo.17, align 8
  %.7092 = alloca i32, align 4
  store i32 0, ptr %.7092, align 4
  %.7127 = alloca double, align 8
  store double 0.000000e+00, ptr %.7127, align 8
  %excinfo.18 = alloca ptr, align 8
  store ptr null, ptr %excinfo.18, align 8
  %.7307 = alloca i32, align 4
  store i32 0, ptr %.7307, align 4
  %.7342 = alloca double, align 8
  store double 0.000000e+00, ptr %.7342, align 8
  %excinfo.19 = alloca ptr, align 8
  store ptr null, ptr %excinfo.19, align 8
  tail call void @NRT_incref(ptr %arg.y.0)
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.ipar.0)
  tail call void @NRT_incref(ptr %arg.st.0)
  tail call void @NRT_incref(ptr %arg.ist.0)
  tail call void @NRT_incref(ptr %arg.t_eval.0)
  tail call void @NRT_incref(ptr %arg.T_out.0)
  tail call void @NRT_incref(ptr %arg.Y_out.0)
  tail call void @NRT_incref(ptr %arg.log.0)
  tail call void @NRT_incref(ptr %arg.mon.0)
  tail call void @NRT_incref(ptr %arg.K.0)
  tail call void @NRT_incref(ptr %arg.F.0)
  tail call void @NRT_incref(ptr %arg.ytmp.0)
  tail call void @NRT_incref(ptr %arg.ynew.0)
  tail call void @NRT_incref(ptr %arg.inv.0)
  tail call void @NRT_incref(ptr %arg.Seg.0)
  tail call void @NRT_incref(ptr %arg.ISeg.0)
  %.309.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.y.0, 0
  %.309.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.0.insert, ptr %arg.y.1, 1
  %.309.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.1.insert, i64 %arg.y.2, 2
  %.309.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.2.insert, i64 %arg.y.3, 3
  %.309.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.3.insert, ptr %arg.y.4, 4
  %.309.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.4.insert, i64 %arg.y.5.0, 5, 0
  %.309.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.5.0.insert, i64 %arg.y.6.0, 6, 0
  %.348 = load i64, ptr %arg.ist.4, align 8
  %.380 = getelementptr i8, ptr %arg.ist.4, i64 24
  %.381 = load i64, ptr %.380, align 8
  %.414 = getelementptr i8, ptr %arg.ist.4, i64 80
  %.415 = load i64, ptr %.414, align 8
  %.459 = load double, ptr %arg.st.4, align 8
  %.491 = getelementptr i8, ptr %arg.st.4, i64 16
  %.492 = load double, ptr %.491, align 8
  %.524 = getelementptr i8, ptr %arg.st.4, i64 56
  %.525 = load double, ptr %.524, align 8
  %.557 = getelementptr i8, ptr %arg.st.4, i64 32
  %.558 = load double, ptr %.557, align 8
  %.590 = getelementptr i8, ptr %arg.st.4, i64 40
  %.591 = load double, ptr %.590, align 8
  %.1265.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.par.0, 0
  %.1265.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.0.insert, ptr %arg.par.1, 1
  %.1265.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.1.insert, i64 %arg.par.2, 2
  %.1265.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.2.insert, i64 %arg.par.3, 3
  %.1265.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.3.insert, ptr %arg.par.4, 4
  %.1265.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.4.insert, i64 %arg.par.5.0, 5, 0
  %.1265.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.5.0.insert, i64 %arg.par.6.0, 6, 0
  %.1266.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ipar.0, 0
  %.1266.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.0.insert, ptr %arg.ipar.1, 1
  %.1266.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.1.insert, i64 %arg.ipar.2, 2
  %.1266.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.2.insert, i64 %arg.ipar.3, 3
  %.1266.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.3.insert, ptr %arg.ipar.4, 4
  %.1266.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.4.insert, i64 %arg.ipar.5.0, 5, 0
  %.1266.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.5.0.insert, i64 %arg.ipar.6.0, 6, 0
  %.2686.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.K.0, 0
  %.2686.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.0.insert, ptr %arg.K.1, 1
  %.2686.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.1.insert, i64 %arg.K.5.1, 2
  %.2686.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.2.insert, i64 %arg.K.3, 3
  %.2686.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.3.insert, ptr %arg.K.4, 4
  %.2686.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.4.insert, i64 %arg.K.5.1, 5, 0
  %.2686.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.5.0.insert, i64 %arg.K.6.1, 6, 0
  %.3252 = getelementptr double, ptr %arg.K.4, i64 %arg.K.5.1
  %.4733.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ytmp.0, 0
  %.4733.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.0.insert, ptr %arg.ytmp.1, 1
  %.4733.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.1.insert, i64 %arg.ytmp.2, 2
  %.4733.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.2.insert, i64 %arg.ytmp.3, 3
  %.4733.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.3.insert, ptr %arg.ytmp.4, 4
  %.4733.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.4.insert, i64 %arg.ytmp.5.0, 5, 0
  %.4733.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.5.0.insert, i64 %arg.ytmp.6.0, 6, 0
  %.4863.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.Y_out.0, 0
  %.4863.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.0.insert, ptr %arg.Y_out.1, 1
  %.4863.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.1.insert, i64 %arg.Y_out.5.1, 2
  %.4863.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.2.insert, i64 %arg.Y_out.3, 3
  %.1774.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ynew.0, 0
  %.1774.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.0.insert, ptr %arg.ynew.1, 1
  %.1774.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.1.insert, i64 %arg.ynew.2, 2
  %.1774.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.2.insert, i64 %arg.ynew.3, 3
  %.1774.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.3.insert, ptr %arg.ynew.4, 4
  %.1774.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.4.insert, i64 %arg.ynew.5.0, 5, 0
  %.1774.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.5.0.insert, i64 %arg.ynew.6.0, 6, 0
  %.2189.idx = mul i64 %arg.K.5.1, 96
  %.2189 = getelementptr i8, ptr %arg.K.4, i64 %.2189.idx
  %.2217.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.3.insert, ptr %.2189, 4
  %.2217.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2217.fca.4.insert, i64 %arg.K.5.1, 5, 0
  %.2217.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2217.fca.5.0.insert, i64 %arg.K.6.1, 6, 0
  %.6074.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } poison, ptr %arg.log.0, 0
  %.6074.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.0.insert, ptr %arg.log.1, 1
  %.6074.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.1.insert, i64 %arg.log.2, 2
  %.6074.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.2.insert, i64 %arg.log.3, 3
  %.6074.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.3.insert, ptr %arg.log.4, 4
  %.6074.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.4.insert, i64 %arg.log.5.0, 5, 0
  %.6074.fca.5.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.5.0.insert, i64 %arg.log.5.1, 5, 1
  %.6074.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.5.1.insert, i64 %arg.log.6.0, 6, 0
  %.6074.fca.6.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.6.0.insert, i64 %arg.log.6.1, 6, 1
  %.7291.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.inv.0, 0
  %.7291.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.0.insert, ptr %arg.inv.1, 1
  %.7291.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.1.insert, i64 %arg.inv.2, 2
  %.7291.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.2.insert, i64 %arg.inv.3, 3
  %.7291.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.3.insert, ptr %arg.inv.4, 4
  %.7291.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.4.insert, i64 %arg.inv.5.0, 5, 0
  %.7291.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.5.0.insert, i64 %arg.inv.6.0, 6, 0
  %0 = mul i64 %arg.K.5.1, -96
  %1 = sub i64 %arg.y.4754, %arg.ynew.4755
  %min.iters.check757 = icmp ult i64 %arg.y.2, 4
  %diff.check756 = icmp ult i64 %1, 256
  %or.cond789 = select i1 %min.iters.check757, i1 true, i1 %diff.check756
  %n.vec764 = and i64 %arg.y.2, %const
  %const_mat = add i64 %const, 28
  %n.vec780 = and i64 %arg.y.2, %const_mat
  %min.iters.check = icmp ult i64 %arg.y.2, 4
  %diff.check = icmp ult i64 %0, 256
  %or.cond788 = select i1 %min.iters.check, i1 true, i1 %diff.check
  %n.vec = and i64 %arg.y.2, %const
  %const_mat1157 = add i64 %const, 28
  %n.vec748 = and i64 %arg.y.2, %const_mat1157
  %scevgep1104 = getelementptr i8, ptr %arg.K.4, i64 192
  %2 = lshr i64 %arg.y.2, 2
  %3 = trunc i64 %2 to i61
  %4 = zext i61 %3 to i64
  %5 = mul nsw i64 %4, -4
  %scevgep1131 = getelementptr i8, ptr %arg.K.4, i64 56
  br label %B276

B276:                                             ; preds = %B3970, %B0
  %t.2.0 = phi double [ %.459, %B0 ], [ %t_new.8.14661, %B3970 ]
  %steps.2.0 = phi i64 [ 0, %B0 ], [ %.6003, %B3970 ]
  %.604 = fcmp ult double %t.2.0, %.492
  br i1 %.604, label %B306, label %B288

B288:                                             ; preds = %B276
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B306:                                             ; preds = %B276
  %sunkaddr = getelementptr i8, ptr %arg.ist.4, i64 64
  %.768 = load i64, ptr %sunkaddr, align 8
  %.770.not = icmp slt i64 %steps.2.0, %.768
  br i1 %.770.not, label %B344, label %B340

B340:                                             ; preds = %B306
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B344:                                             ; preds = %B306
  %6 = icmp eq i64 %.381, 0
  br i1 %6, label %B348, label %B422

B348:                                             ; preds = %B344
  %sunkaddr1158 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.935 = load i64, ptr %sunkaddr1158, align 8
  %.951.not = icmp slt i64 %.935, %arg.Y_out.5.0
  br i1 %.951.not, label %B422, label %B404

B404:                                             ; preds = %B348
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B422:                                             ; preds = %B348, %B344
  %7 = icmp eq i64 %.415, 0
  br i1 %7, label %B500, label %B426

B426:                                             ; preds = %B422
  %sunkaddr1159 = getelementptr i8, ptr %arg.ist.4, i64 88
  %.1115 = load i64, ptr %sunkaddr1159, align 8
  %.1131.not = icmp slt i64 %.1115, %arg.Seg.5.0
  br i1 %.1131.not, label %B500, label %B482

B482:                                             ; preds = %B426
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B500:                                             ; preds = %B426, %B422
  %8 = icmp eq ptr %arg.cap.2, null
  br i1 %8, label %B500.if, label %B500.else, !prof !0

B608:                                             ; preds = %B500.endif
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B626:                                             ; preds = %B500.endif
  %9 = icmp eq i64 %.381, 0
  br i1 %9, label %B734, label %B634

B634:                                             ; preds = %B626
  %sunkaddr1160 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.1561 = load i64, ptr %sunkaddr1160, align 8
  %.1563 = icmp slt i64 %.1561, %arg.t_eval.2
  br i1 %.1563, label %B668, label %B734

B668:                                             ; preds = %B634
  %.1608 = icmp slt i64 %.1561, 0
  %.1609 = select i1 %.1608, i64 %arg.t_eval.5.0, i64 0
  %10 = getelementptr double, ptr %arg.t_eval.4, i64 %.1561
  %.1623 = getelementptr double, ptr %10, i64 %.1609
  %.1624 = load double, ptr %.1623, align 8
  %.12.i = fcmp olt double %.1624, %.492
  %.13.i = select i1 %.12.i, double %.1624, double %.492
  br label %B734

B734:                                             ; preds = %B668, %B634, %B626
  %t_next.2.1 = phi double [ %.492, %B626 ], [ %.492, %B634 ], [ %.13.i, %B668 ]
  %11 = icmp eq i64 %.348, 0
  br i1 %11, label %B756.endif, label %B1156

B956:                                             ; preds = %B860.endif
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B974:                                             ; preds = %B860.endif
  %.2013 = fcmp olt double %.1801, %.525
  br i1 %.2013, label %B986, label %B1004

B986:                                             ; preds = %B974
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B1004:                                            ; preds = %B974
  %12 = icmp eq i64 %.415, 0
  br i1 %12, label %B3062.endif, label %B1008

B1008:                                            ; preds = %B1004
  %13 = icmp eq ptr %arg.rhs.2, null
  call void @NRT_incref(ptr %arg.K.0)
  br i1 %13, label %B1008.if, label %B1008.else, !prof !0

B1156:                                            ; preds = %B734
  %sunkaddr1161 = getelementptr i8, ptr %arg.ist.4, i64 72
  %.2616 = load i64, ptr %sunkaddr1161, align 8
  %.2617.not = icmp eq i64 %.2616, 0
  br i1 %.2617.not, label %B1306, label %B1190

B1190:                                            ; preds = %B1156
  %14 = icmp eq ptr %arg.rhs.2, null
  call void @NRT_incref(ptr %arg.K.0)
  br i1 %14, label %B1190.if, label %B1190.else, !prof !0

B1306:                                            ; preds = %B1190.endif, %B1156
  %sunkaddr1162 = getelementptr i8, ptr %arg.st.4, i64 64
  %.2929 = load double, ptr %sunkaddr1162, align 8
  %.2931 = fcmp olt double %.2929, %.525
  br i1 %.2931, label %B1340, label %B1406

B1340:                                            ; preds = %B1306
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  %sunkaddr1163 = getelementptr i8, ptr %arg.st.4, i64 64
  %.3085 = load double, ptr %sunkaddr1163, align 8
  %.3086 = fcmp ult double %.3085, 0.000000e+00
  br i1 %.3086, label %B1388, label %B4012

B1388:                                            ; preds = %B1340
  br label %B4012

B1406:                                            ; preds = %B1306
  %sunkaddr1164 = getelementptr i8, ptr %arg.st.4, i64 8
  %.3135 = load double, ptr %sunkaddr1164, align 8
  %.3136 = fcmp ugt double %.3135, 0.000000e+00
  br i1 %.3136, label %B1406.B1648.preheader_crit_edge, label %B1440

B1406.B1648.preheader_crit_edge:                  ; preds = %B1406
  %.pre = fsub double %.492, %t.2.0
  br label %B1648.preheader

B1440:                                            ; preds = %B1406
  call void @NRT_incref(ptr %arg.K.0)
  %.3212 = fsub double %.492, %t.2.0
  call void @NRT_incref(ptr %arg.K.0)
  store double 0.000000e+00, ptr %.3291, align 8
  %.3305 = call i32 @_ZN6charts7solvers2rk12initial_stepB3v84B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdddd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.3291, ptr nonnull %excinfo.8, ptr %arg.rhs.0, ptr %arg.rhs.1, ptr %arg.rhs.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.1, i64 %arg.K.6.1, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, double %.3212, double %.1274.0, double %.558, double %.591, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.3252, i64 %arg.K.5.1, i64 %arg.K.6.1)
  %cond231 = icmp eq i32 %.3305, 0
  br i1 %cond231, label %B1440.endif, label %B1440.if.if, !prof !1

B1648.preheader:                                  ; preds = %B1406.B1648.preheader_crit_edge, %B1440.endif
  %.3596.pre-phi = phi double [ %.pre, %B1406.B1648.preheader_crit_edge ], [ %.3212, %B1440.endif ]
  %.3464 = phi double [ %.3135, %B1406.B1648.preheader_crit_edge ], [ %.3464.pre, %B1440.endif ]
  %.12.i189 = fcmp olt double %.1274.0, %.3464
  %.13.i190 = select i1 %.12.i189, double %.1274.0, double %.3464
  %.3541.peel173 = call double @numba_nextafter(double %t.2.0, double 0x7FF0000000000000)
  %.3547.peel174 = fsub double %.3541.peel173, %t.2.0
  %.3548.peel175 = fmul double %.3547.peel174, 1.000000e+01
  %.3550.peel176 = fcmp olt double %.13.i190, %.3548.peel175
  br i1 %.3550.peel176, label %B2192, label %B1752.peel.preheader

B1752.peel.preheader:                             ; preds = %B1648.preheader
  br label %B1752.peel

B1752.peel:                                       ; preds = %B1752.peel.preheader, %B1942
  %15 = phi i1 [ false, %B1942 ], [ true, %B1752.peel.preheader ]
  %h.8.2177 = phi double [ %.3755, %B1942 ], [ %.13.i190, %B1752.peel.preheader ]
  %.3584.peel = fadd double %t.2.0, %h.8.2177
  %.3586.peel = fcmp oge double %.3584.peel, %.492
  %h.9.5.peel = select i1 %.3586.peel, double %.3596.pre-phi, double %h.8.2177
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(16) %.3622, i8 0, i64 16, i1 false)
  %.3638.peel = call i32 @_ZN6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd(ptr nonnull %.3622, ptr nonnull %excinfo.10, ptr %arg.rhs.0, ptr %arg.rhs.1, ptr %arg.rhs.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %h.9.5.peel, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %.558, double %.591)
  %.3648.fca.0.load.peel = load double, ptr %.3622, align 8
  %sunkaddr1165 = getelementptr inbounds i8, ptr %.3622, i64 8
  %.3648.fca.1.load.peel = load double, ptr %sunkaddr1165, align 8
  %cond228 = icmp eq i32 %.3638.peel, 0
  br i1 %cond228, label %B1796.endif.peel, label %B1796.if.if, !prof !1

B1796.endif.peel:                                 ; preds = %B1752.peel
  %sunkaddr1166 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.3701.peel = load i64, ptr %sunkaddr1166, align 8
  %.3702.peel = add nsw i64 %.3701.peel, 12
  store i64 %.3702.peel, ptr %sunkaddr1166, align 8
  %.3734.peel = fcmp uge double %.3648.fca.1.load.peel, 0.000000e+00
  %.3737.peel = fsub double %.3648.fca.0.load.peel, %.3648.fca.0.load.peel
  %.3738.peel = fcmp ord double %.3737.peel, 0.000000e+00
  %or.cond.peel = select i1 %.3734.peel, i1 %.3738.peel, i1 false
  br i1 %or.cond.peel, label %B2010.peel, label %B1942

B2010.peel:                                       ; preds = %B1796.endif.peel
  %.3826.peel = fcmp olt double %.3648.fca.1.load.peel, %.525
  br i1 %.3826.peel, label %B2192, label %B2038.peel

B2038.peel:                                       ; preds = %B2010.peel
  %.20.i = fcmp olt double %.3648.fca.0.load.peel, 1.000000e+00
  br i1 %.20.i, label %B16.i, label %B2110.peel

B16.i:                                            ; preds = %B2038.peel
  %.23.i = fcmp oeq double %.3648.fca.0.load.peel, 0.000000e+00
  br i1 %.23.i, label %B2038.endif.peel.thread, label %B44.i

B44.i:                                            ; preds = %B16.i
  %.32.i = call double @llvm.pow.f64(double %.3648.fca.0.load.peel, double -1.250000e-01)
  %.35.i = fmul double %.32.i, 9.000000e-01
  %.12.i.i = fcmp olt double %.35.i, 1.000000e+01
  %.13.i.i = select i1 %.12.i.i, double %.35.i, double 1.000000e+01
  br label %B2038.endif.peel.thread

B2038.endif.peel.thread:                          ; preds = %B16.i, %B44.i
  %fac.3.0.i = phi double [ 1.000000e+01, %B16.i ], [ %.13.i.i, %B44.i ]
  %.12.i1.i = fcmp olt double %fac.3.0.i, 1.000000e+00
  %16 = or i1 %15, %.12.i1.i
  %fac.4.0.i = select i1 %16, double %fac.3.0.i, double 1.000000e+00
  br label %B2196

B2110.peel:                                       ; preds = %B2038.peel
  %.121.i = call double @llvm.pow.f64(double %.3648.fca.0.load.peel, double -1.250000e-01)
  %.124.i = fmul double %.121.i, 9.000000e-01
  %.12.i3.i = fcmp ogt double %.124.i, 2.000000e-01
  %.13.i4.i = select i1 %.12.i3.i, double %.124.i, double 2.000000e-01
  %.3958.peel = fmul double %h.9.5.peel, %.13.i4.i
  %sunkaddr1167 = getelementptr i8, ptr %arg.ist.4, i64 48
  %storemerge.in161 = load i64, ptr %sunkaddr1167, align 8
  %storemerge162 = add nsw i64 %storemerge.in161, 1
  store i64 %storemerge162, ptr %sunkaddr1167, align 8
  %.3541163 = call double @numba_nextafter(double %t.2.0, double 0x7FF0000000000000)
  %.3547164 = fsub double %.3541163, %t.2.0
  %.3548165 = fmul double %.3547164, 1.000000e+01
  %.3550166 = fcmp olt double %.3958.peel, %.3548165
  br i1 %.3550166, label %B2192, label %B1752.preheader

B1752.preheader:                                  ; preds = %B2110.peel
  br label %B1752

B1752:                                            ; preds = %B1752.preheader, %B2110
  %h.7.3167 = phi double [ %.3958, %B2110 ], [ %.3958.peel, %B1752.preheader ]
  %.3584 = fadd double %t.2.0, %h.7.3167
  %.3586 = fcmp oge double %.3584, %.492
  %h.9.5 = select i1 %.3586, double %.3596.pre-phi, double %h.7.3167
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(16) %.3622, i8 0, i64 16, i1 false)
  %.3638 = call i32 @_ZN6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd(ptr nonnull %.3622, ptr nonnull %excinfo.10, ptr %arg.rhs.0, ptr %arg.rhs.1, ptr %arg.rhs.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %h.9.5, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %.558, double %.591)
  %.3648.fca.0.load = load double, ptr %.3622, align 8
  %sunkaddr1168 = getelementptr inbounds i8, ptr %.3622, i64 8
  %.3648.fca.1.load = load double, ptr %sunkaddr1168, align 8
  %cond230 = icmp eq i32 %.3638, 0
  br i1 %cond230, label %B1796.endif, label %B1796.if.if, !prof !1

B1942:                                            ; preds = %B1796.endif, %B1796.endif.peel
  %h.9.5.lcssa4881 = phi double [ %h.9.5.peel, %B1796.endif.peel ], [ %h.9.5, %B1796.endif ]
  %.3755 = fmul double %h.9.5.lcssa4881, 2.000000e-01
  %sunkaddr1169 = getelementptr i8, ptr %arg.ist.4, i64 48
  %.3791 = load i64, ptr %sunkaddr1169, align 8
  %.3792 = add nsw i64 %.3791, 1
  store i64 %.3792, ptr %sunkaddr1169, align 8
  %.3541.peel = call double @numba_nextafter(double %t.2.0, double 0x7FF0000000000000)
  %.3547.peel = fsub double %.3541.peel, %t.2.0
  %.3548.peel = fmul double %.3547.peel, 1.000000e+01
  %.3550.peel = fcmp olt double %.3755, %.3548.peel
  br i1 %.3550.peel, label %B2192, label %B1752.peel

B2010:                                            ; preds = %B1796.endif
  %.3826 = fcmp olt double %.3648.fca.1.load, %.525
  br i1 %.3826, label %B2192, label %B2038

B2038:                                            ; preds = %B2010
  %.20.i191 = fcmp olt double %.3648.fca.0.load, 1.000000e+00
  br i1 %.20.i191, label %B16.i198, label %B2110

B16.i198:                                         ; preds = %B2038
  %.23.i199 = fcmp oeq double %.3648.fca.0.load, 0.000000e+00
  br i1 %.23.i199, label %B2038.endif.thread, label %B44.i200

B44.i200:                                         ; preds = %B16.i198
  %.32.i201 = call double @llvm.pow.f64(double %.3648.fca.0.load, double -1.250000e-01)
  %.35.i202 = fmul double %.32.i201, 9.000000e-01
  %.12.i.i203 = fcmp olt double %.35.i202, 1.000000e+01
  %.13.i.i204 = select i1 %.12.i.i203, double %.35.i202, double 1.000000e+01
  br label %B2038.endif.thread

B2038.endif.thread:                               ; preds = %B16.i198, %B44.i200
  %fac.3.0.i206 = phi double [ 1.000000e+01, %B16.i198 ], [ %.13.i.i204, %B44.i200 ]
  %.12.i1.i207 = fcmp olt double %fac.3.0.i206, 1.000000e+00
  %fac.4.0.i208 = select i1 %.12.i1.i207, double %fac.3.0.i206, double 1.000000e+00
  br label %B2196

B2110:                                            ; preds = %B2038
  %.121.i193 = call double @llvm.pow.f64(double %.3648.fca.0.load, double -1.250000e-01)
  %.124.i194 = fmul double %.121.i193, 9.000000e-01
  %.12.i3.i195 = fcmp ogt double %.124.i194, 2.000000e-01
  %.13.i4.i196 = select i1 %.12.i3.i195, double %.124.i194, double 2.000000e-01
  %.3958 = fmul double %h.9.5, %.13.i4.i196
  %sunkaddr1170 = getelementptr i8, ptr %arg.ist.4, i64 48
  %storemerge.in = load i64, ptr %sunkaddr1170, align 8
  %storemerge = add nsw i64 %storemerge.in, 1
  store i64 %storemerge, ptr %sunkaddr1170, align 8
  %.3541 = call double @numba_nextafter(double %t.2.0, double 0x7FF0000000000000)
  %.3547 = fsub double %.3541, %t.2.0
  %.3548 = fmul double %.3547, 1.000000e+01
  %.3550 = fcmp olt double %.3958, %.3548
  br i1 %.3550, label %B2192, label %B1752, !llvm.loop !2

B2192:                                            ; preds = %B1648.preheader, %B1942, %B2010.peel, %B2110.peel, %B2010, %B2110
  %status.14.2.ph = phi i64 [ -3, %B2110 ], [ -3, %B2110.peel ], [ -1, %B2010 ], [ -3, %B1942 ], [ -1, %B2010.peel ], [ -3, %B1648.preheader ]
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B2196:                                            ; preds = %B2038.endif.thread, %B2038.endif.peel.thread
  %.3870.lcssa4890 = phi double [ %fac.4.0.i208, %B2038.endif.thread ], [ %fac.4.0.i, %B2038.endif.peel.thread ]
  %.3584.lcssa4889 = phi double [ %.3584, %B2038.endif.thread ], [ %.3584.peel, %B2038.endif.peel.thread ]
  %.3586.lcssa4886 = phi i1 [ %.3586, %B2038.endif.thread ], [ %.3586.peel, %B2038.endif.peel.thread ]
  %h.9.5.lcssa4883 = phi double [ %h.9.5, %B2038.endif.thread ], [ %h.9.5.peel, %B2038.endif.peel.thread ]
  %.3648.fca.1.load.lcssa4877 = phi double [ %.3648.fca.1.load, %B2038.endif.thread ], [ %.3648.fca.1.load.peel, %B2038.endif.peel.thread ]
  %17 = icmp eq i64 %.415, 0
  %t_new.10.5.le = select i1 %.3586.lcssa4886, double %.492, double %.3584.lcssa4889
  %.3910 = fmul double %.3870.lcssa4890, %h.9.5.lcssa4883
  %sunkaddr1171 = getelementptr i8, ptr %arg.st.4, i64 8
  store double %.3910, ptr %sunkaddr1171, align 8
  %sunkaddr1172 = getelementptr i8, ptr %arg.st.4, i64 64
  store double %.3648.fca.1.load.lcssa4877, ptr %sunkaddr1172, align 8
  br i1 %17, label %B2220, label %B2304

B2220:                                            ; preds = %B2196
  %18 = icmp eq i64 %.381, 0
  br i1 %18, label %B3062.endif, label %B2224

B2224:                                            ; preds = %B2220
  %sunkaddr1173 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.4230 = load i64, ptr %sunkaddr1173, align 8
  %.4232 = icmp slt i64 %.4230, %arg.t_eval.2
  br i1 %.4232, label %B2258, label %B2394

B2258:                                            ; preds = %B2224
  %.4277 = icmp slt i64 %.4230, 0
  %.4278 = select i1 %.4277, i64 %arg.t_eval.5.0, i64 0
  %19 = getelementptr double, ptr %arg.t_eval.4, i64 %.4230
  %.4292 = getelementptr double, ptr %19, i64 %.4278
  %.4293 = load double, ptr %.4292, align 8
  %.4295 = fcmp olt double %.4293, %t_new.10.5.le
  br i1 %.4295, label %B2304, label %B2394

B2304:                                            ; preds = %B2258, %B2196
  store ptr null, ptr %.4306, align 8
  %.4326 = call i32 @_ZN6charts7solvers2rk12dop853_denseB3v92B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE(ptr nonnull %.4306, ptr nonnull %excinfo.12, ptr %arg.rhs.0, ptr %arg.rhs.1, ptr %arg.rhs.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %h.9.5.lcssa4883, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.F.0, ptr %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1)
  %cond229 = icmp eq i32 %.4326, 0
  br i1 %cond229, label %B2390, label %B2304.if.if, !prof !1

B2390:                                            ; preds = %B2304
  %20 = icmp eq i64 %.381, 0
  %sunkaddr1174 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.4375 = load i64, ptr %sunkaddr1174, align 8
  %.4376 = add nsw i64 %.4375, 3
  store i64 %.4376, ptr %sunkaddr1174, align 8
  br i1 %20, label %B2898, label %B2390.B2394_crit_edge

B2390.B2394_crit_edge:                            ; preds = %B2390
  %sunkaddr1175 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.4457.pre = load i64, ptr %sunkaddr1175, align 8
  br label %B2394

B2394:                                            ; preds = %B2390.B2394_crit_edge, %B2224, %B2258
  %.4457 = phi i64 [ %.4457.pre, %B2390.B2394_crit_edge ], [ %.4230, %B2224 ], [ %.4230, %B2258 ]
  %.4459 = icmp slt i64 %.4457, %arg.t_eval.2
  br i1 %.4459, label %B2428, label %B2898

B2428:                                            ; preds = %B2394
  %.4513 = icmp slt i64 %.4457, 0
  %.4514 = select i1 %.4513, i64 %arg.t_eval.5.0, i64 0
  %21 = getelementptr double, ptr %arg.t_eval.4, i64 %.4457
  %.4528 = getelementptr double, ptr %21, i64 %.4514
  %.4529 = load double, ptr %.4528, align 8
  %.4531 = fcmp olt double %.4529, %t_new.10.5.le
  br i1 %.4531, label %B2554.preheader, label %B2898

B2554.preheader:                                  ; preds = %B2428
  %.4723 = fcmp oeq double %h.9.5.lcssa4883, 0.000000e+00
  br i1 %.4723, label %B2554.if, label %B2554.preheader1046, !prof !0

B2554.preheader1046:                              ; preds = %B2554.preheader
  br label %B2554

B2554:                                            ; preds = %B2554.preheader1046, %B2852
  %.4688 = phi i64 [ %.5109, %B2852 ], [ %.4457, %B2554.preheader1046 ]
  %.4702 = icmp slt i64 %.4688, 0
  %.4703 = select i1 %.4702, i64 %arg.t_eval.5.0, i64 0
  %22 = getelementptr double, ptr %arg.t_eval.4, i64 %.4688
  %.4717 = getelementptr double, ptr %22, i64 %.4703
  %.4718 = load double, ptr %.4717, align 8
  %.4721 = fsub double %.4718, %t.2.0
  %.4730 = fdiv double %.4721, %h.9.5.lcssa4883
  store ptr null, ptr %.4734, align 8
  %.4746 = call i32 @_ZN6charts7solvers2rk10dense_evalB3v94B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.4734, ptr nonnull %excinfo.13, ptr %arg.F.0, ptr %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %.4730, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0)
  switch i32 %.4746, label %B2554.endif.if.if [
    i32 -2, label %B2554.endif.endif
    i32 0, label %B2554.endif.endif
  ], !prof !4

B2852:                                            ; preds = %B2554.endif.endif.endif
  %.5225 = icmp slt i64 %.5108, -1
  %.5226 = select i1 %.5225, i64 %arg.t_eval.5.0, i64 0
  %23 = getelementptr double, ptr %arg.t_eval.4, i64 %.5109
  %.5240 = getelementptr double, ptr %23, i64 %.5226
  %.5241 = load double, ptr %.5240, align 8
  %.5243 = fcmp olt double %.5241, %t_new.10.5.le
  br i1 %.5243, label %B2554, label %B2898

B2898:                                            ; preds = %B2554.endif.endif.endif, %B2852, %B2428, %B2394, %B2390
  %24 = icmp eq i64 %.415, 0
  br i1 %24, label %B3062.endif, label %B2902

B2902:                                            ; preds = %B2898.thread4678, %B2898
  %t_new.8.14705 = phi double [ %t_new.9.1, %B2898.thread4678 ], [ %t_new.10.5.le, %B2898 ]
  %sunkaddr1176 = getelementptr i8, ptr %arg.ist.4, i64 88
  %.5290 = load i64, ptr %sunkaddr1176, align 8
  %.5309 = icmp slt i64 %.5290, 0
  %.5310 = select i1 %.5309, i64 %arg.Seg.5.0, i64 0
  %.5311 = add i64 %.5310, %.5290
  %.5328 = mul i64 %.5311, %arg.Seg.5.1
  %.5330 = getelementptr double, ptr %arg.Seg.4, i64 %.5328
  call void @NRT_incref(ptr %arg.Seg.0)
  %.5391 = load i64, ptr %sunkaddr1176, align 8
  %.5410 = icmp slt i64 %.5391, 0
  %.5411 = select i1 %.5410, i64 %arg.ISeg.5.0, i64 0
  %.5412 = add i64 %.5411, %.5391
  %.5429 = mul i64 %.5412, %arg.ISeg.5.1
  %.5431 = getelementptr i64, ptr %arg.ISeg.4, i64 %.5429
  call void @NRT_incref(ptr %arg.ISeg.0)
  %.5465 = fsub double %t_new.8.14705, %t.2.0
  store ptr null, ptr %.5471, align 8
  %.5489 = call i32 @_ZN6charts7solvers4loop15_record_segmentB3v95B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedEdd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE(ptr nonnull %.5471, ptr nonnull %excinfo.15, ptr %arg.Seg.0, ptr %arg.Seg.1, i64 %arg.Seg.5.1, i64 %arg.Seg.3, ptr %.5330, i64 %arg.Seg.5.1, i64 %arg.Seg.6.1, ptr %arg.ISeg.0, ptr %arg.ISeg.1, i64 %arg.ISeg.5.1, i64 %arg.ISeg.3, ptr %.5431, i64 %arg.ISeg.5.1, i64 %arg.ISeg.6.1, double %t.2.0, double %.5465, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.F.0, ptr %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0)
  switch i32 %.5489, label %B2902.if.if [
    i32 -2, label %B2902.endif
    i32 0, label %B2902.endif
  ], !prof !4

B3094:                                            ; preds = %B3094.preheader1045, %B3094
  %.566748564858 = phi i64 [ %.5674.7, %B3094 ], [ %.566748564858.unr, %B3094.preheader1045 ]
  %sunkaddr1177 = mul i64 %.566748564858, 8
  %sunkaddr1178 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1177
  %.5728 = load double, ptr %sunkaddr1178, align 8
  %sunkaddr1179 = mul i64 %.566748564858, 8
  %sunkaddr1180 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1179
  store double %.5728, ptr %sunkaddr1180, align 8
  %sunkaddr1181 = mul i64 %.566748564858, 8
  %sunkaddr1182 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1181
  %sunkaddr1183 = getelementptr i8, ptr %sunkaddr1182, i64 8
  %.5728.1 = load double, ptr %sunkaddr1183, align 8
  %sunkaddr1184 = mul i64 %.566748564858, 8
  %sunkaddr1185 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1184
  %sunkaddr1186 = getelementptr i8, ptr %sunkaddr1185, i64 8
  store double %.5728.1, ptr %sunkaddr1186, align 8
  %sunkaddr1187 = mul i64 %.566748564858, 8
  %sunkaddr1188 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1187
  %sunkaddr1189 = getelementptr i8, ptr %sunkaddr1188, i64 16
  %.5728.2 = load double, ptr %sunkaddr1189, align 8
  %sunkaddr1190 = mul i64 %.566748564858, 8
  %sunkaddr1191 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1190
  %sunkaddr1192 = getelementptr i8, ptr %sunkaddr1191, i64 16
  store double %.5728.2, ptr %sunkaddr1192, align 8
  %sunkaddr1193 = mul i64 %.566748564858, 8
  %sunkaddr1194 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1193
  %sunkaddr1195 = getelementptr i8, ptr %sunkaddr1194, i64 24
  %.5728.3 = load double, ptr %sunkaddr1195, align 8
  %sunkaddr1196 = mul i64 %.566748564858, 8
  %sunkaddr1197 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1196
  %sunkaddr1198 = getelementptr i8, ptr %sunkaddr1197, i64 24
  store double %.5728.3, ptr %sunkaddr1198, align 8
  %sunkaddr1199 = mul i64 %.566748564858, 8
  %sunkaddr1200 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1199
  %sunkaddr1201 = getelementptr i8, ptr %sunkaddr1200, i64 32
  %.5728.4 = load double, ptr %sunkaddr1201, align 8
  %sunkaddr1202 = mul i64 %.566748564858, 8
  %sunkaddr1203 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1202
  %sunkaddr1204 = getelementptr i8, ptr %sunkaddr1203, i64 32
  store double %.5728.4, ptr %sunkaddr1204, align 8
  %sunkaddr1205 = mul i64 %.566748564858, 8
  %sunkaddr1206 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1205
  %sunkaddr1207 = getelementptr i8, ptr %sunkaddr1206, i64 40
  %.5728.5 = load double, ptr %sunkaddr1207, align 8
  %sunkaddr1208 = mul i64 %.566748564858, 8
  %sunkaddr1209 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1208
  %sunkaddr1210 = getelementptr i8, ptr %sunkaddr1209, i64 40
  store double %.5728.5, ptr %sunkaddr1210, align 8
  %sunkaddr1211 = mul i64 %.566748564858, 8
  %sunkaddr1212 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1211
  %sunkaddr1213 = getelementptr i8, ptr %sunkaddr1212, i64 48
  %.5728.6 = load double, ptr %sunkaddr1213, align 8
  %sunkaddr1214 = mul i64 %.566748564858, 8
  %sunkaddr1215 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1214
  %sunkaddr1216 = getelementptr i8, ptr %sunkaddr1215, i64 48
  store double %.5728.6, ptr %sunkaddr1216, align 8
  %.5674.7 = add nuw nsw i64 %.566748564858, 8
  %sunkaddr1217 = mul i64 %.566748564858, 8
  %sunkaddr1218 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1217
  %sunkaddr1219 = getelementptr i8, ptr %sunkaddr1218, i64 56
  %.5728.7 = load double, ptr %sunkaddr1219, align 8
  %sunkaddr1220 = mul i64 %.566748564858, 8
  %sunkaddr1221 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1220
  %sunkaddr1222 = getelementptr i8, ptr %sunkaddr1221, i64 56
  store double %.5728.7, ptr %sunkaddr1222, align 8
  %exitcond.not.7 = icmp eq i64 %arg.y.2, %.5674.7
  br i1 %exitcond.not.7, label %B3120, label %B3094, !llvm.loop !5

B3120:                                            ; preds = %B3094, %B3094.prol.loopexit, %vec.epilog.middle.block785, %middle.block772
  %25 = icmp eq i64 %.348, 1
  br i1 %25, label %iter.check, label %B3208

iter.check:                                       ; preds = %B3120
  br i1 %or.cond788, label %B3174.preheader, label %vector.main.loop.iter.check

vector.main.loop.iter.check:                      ; preds = %iter.check
  %26 = icmp ult i64 %arg.y.2, 32
  br i1 %26, label %vec.epilog.ph, label %vector.body.preheader

vector.body.preheader:                            ; preds = %vector.main.loop.iter.check
  br label %vector.body

vector.body:                                      ; preds = %vector.body.preheader, %vector.body
  %lsr.iv1105 = phi ptr [ %scevgep1104, %vector.body.preheader ], [ %scevgep1106, %vector.body ]
  %lsr.iv1102 = phi i64 [ %n.vec764, %vector.body.preheader ], [ %lsr.iv.next1103, %vector.body ]
  %scevgep1115 = getelementptr i8, ptr %lsr.iv1105, i64 %.2189.idx
  %scevgep1116 = getelementptr i8, ptr %scevgep1115, i64 -192
  %scevgep1113 = getelementptr i8, ptr %lsr.iv1105, i64 %.2189.idx
  %scevgep1114 = getelementptr i8, ptr %scevgep1113, i64 -128
  %scevgep1111 = getelementptr i8, ptr %lsr.iv1105, i64 %.2189.idx
  %scevgep1112 = getelementptr i8, ptr %scevgep1111, i64 -64
  %scevgep1110 = getelementptr i8, ptr %lsr.iv1105, i64 %.2189.idx
  %wide.load = load <8 x double>, ptr %scevgep1116, align 8
  %wide.load744 = load <8 x double>, ptr %scevgep1114, align 8
  %wide.load745 = load <8 x double>, ptr %scevgep1112, align 8
  %wide.load746 = load <8 x double>, ptr %scevgep1110, align 8
  %scevgep1109 = getelementptr i8, ptr %lsr.iv1105, i64 -192
  %scevgep1108 = getelementptr i8, ptr %lsr.iv1105, i64 -128
  %scevgep1107 = getelementptr i8, ptr %lsr.iv1105, i64 -64
  store <8 x double> %wide.load, ptr %scevgep1109, align 8
  store <8 x double> %wide.load744, ptr %scevgep1108, align 8
  store <8 x double> %wide.load745, ptr %scevgep1107, align 8
  store <8 x double> %wide.load746, ptr %lsr.iv1105, align 8
  %lsr.iv.next1103 = add i64 %lsr.iv1102, -32
  %scevgep1106 = getelementptr i8, ptr %lsr.iv1105, i64 256
  %27 = icmp eq i64 %lsr.iv.next1103, 0
  br i1 %27, label %middle.block, label %vector.body, !llvm.loop !7

middle.block:                                     ; preds = %vector.body
  %28 = icmp eq i64 %arg.y.2, %n.vec
  br i1 %28, label %B3208, label %vec.epilog.iter.check

vec.epilog.iter.check:                            ; preds = %middle.block
  %29 = and i64 %arg.y.2, 28
  %30 = icmp eq i64 %29, 0
  br i1 %30, label %B3174.preheader, label %vec.epilog.ph, !prof !9

vec.epilog.ph:                                    ; preds = %vector.main.loop.iter.check, %vec.epilog.iter.check
  %vec.epilog.resume.val = phi i64 [ %n.vec, %vec.epilog.iter.check ], [ 0, %vector.main.loop.iter.check ]
  %31 = add i64 %5, %vec.epilog.resume.val
  %32 = shl i64 %vec.epilog.resume.val, 3
  %scevgep1119 = getelementptr i8, ptr %arg.K.4, i64 %32
  br label %vec.epilog.vector.body

vec.epilog.vector.body:                           ; preds = %vec.epilog.vector.body, %vec.epilog.ph
  %lsr.iv1120 = phi ptr [ %scevgep1121, %vec.epilog.vector.body ], [ %scevgep1119, %vec.epilog.ph ]
  %lsr.iv1117 = phi i64 [ %lsr.iv.next1118, %vec.epilog.vector.body ], [ %31, %vec.epilog.ph ]
  %scevgep1122 = getelementptr i8, ptr %lsr.iv1120, i64 %.2189.idx
  %wide.load750 = load <4 x double>, ptr %scevgep1122, align 8
  store <4 x double> %wide.load750, ptr %lsr.iv1120, align 8
  %lsr.iv.next1118 = add i64 %lsr.iv1117, 4
  %scevgep1121 = getelementptr i8, ptr %lsr.iv1120, i64 32
  %33 = icmp eq i64 %lsr.iv.next1118, 0
  br i1 %33, label %vec.epilog.middle.block, label %vec.epilog.vector.body, !llvm.loop !10

vec.epilog.middle.block:                          ; preds = %vec.epilog.vector.body
  %34 = icmp eq i64 %arg.y.2, %n.vec748
  br i1 %34, label %B3208, label %B3174.preheader

B3174.preheader:                                  ; preds = %iter.check, %vec.epilog.iter.check, %vec.epilog.middle.block
  %.585348624864.ph = phi i64 [ 0, %iter.check ], [ %n.vec, %vec.epilog.iter.check ], [ %n.vec748, %vec.epilog.middle.block ]
  %35 = sub nsw i64 %arg.y.2, %.585348624864.ph
  %xtraiter918 = and i64 %35, 7
  %lcmp.mod919.not = icmp eq i64 %xtraiter918, 0
  br i1 %lcmp.mod919.not, label %B3174.prol.loopexit, label %B3174.prol.preheader

B3174.prol.preheader:                             ; preds = %B3174.preheader
  %36 = shl i64 %.585348624864.ph, 3
  %scevgep1123 = getelementptr i8, ptr %arg.K.4, i64 %36
  %37 = mul nsw i64 %xtraiter918, -1
  br label %B3174.prol

B3174.prol:                                       ; preds = %B3174.prol.preheader, %B3174.prol
  %lsr.iv1127 = phi i64 [ 0, %B3174.prol.preheader ], [ %lsr.iv.next1128, %B3174.prol ]
  %lsr.iv1124 = phi ptr [ %scevgep1123, %B3174.prol.preheader ], [ %scevgep1125, %B3174.prol ]
  %scevgep1126 = getelementptr i8, ptr %lsr.iv1124, i64 %.2189.idx
  %.5938.prol = load double, ptr %scevgep1126, align 8
  store double %.5938.prol, ptr %lsr.iv1124, align 8
  %scevgep1125 = getelementptr i8, ptr %lsr.iv1124, i64 8
  %lsr.iv.next1128 = add nsw i64 %lsr.iv1127, -1
  %prol.iter920.cmp.not = icmp eq i64 %37, %lsr.iv.next1128
  br i1 %prol.iter920.cmp.not, label %B3174.prol.loopexit.loopexit, label %B3174.prol, !llvm.loop !11

B3174.prol.loopexit.loopexit:                     ; preds = %B3174.prol
  %38 = sub i64 %.585348624864.ph, %lsr.iv.next1128
  br label %B3174.prol.loopexit

B3174.prol.loopexit:                              ; preds = %B3174.prol.loopexit.loopexit, %B3174.preheader
  %.585348624864.unr = phi i64 [ %.585348624864.ph, %B3174.preheader ], [ %38, %B3174.prol.loopexit.loopexit ]
  %39 = sub nsw i64 %.585348624864.ph, %arg.y.2
  %40 = icmp ugt i64 %39, -8
  br i1 %40, label %B3208, label %B3174.preheader1044

B3174.preheader1044:                              ; preds = %B3174.prol.loopexit
  %41 = sub i64 %arg.y.2, %.585348624864.unr
  %42 = shl i64 %.585348624864.unr, 3
  %scevgep1132 = getelementptr i8, ptr %scevgep1131, i64 %42
  br label %B3174

B3174:                                            ; preds = %B3174.preheader1044, %B3174
  %lsr.iv1133 = phi ptr [ %scevgep1132, %B3174.preheader1044 ], [ %scevgep1134, %B3174 ]
  %lsr.iv1129 = phi i64 [ %41, %B3174.preheader1044 ], [ %lsr.iv.next1130, %B3174 ]
  %scevgep1153 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1154 = getelementptr i8, ptr %scevgep1153, i64 -56
  %.5938 = load double, ptr %scevgep1154, align 8
  %scevgep1140 = getelementptr i8, ptr %lsr.iv1133, i64 -56
  store double %.5938, ptr %scevgep1140, align 8
  %scevgep1155 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1156 = getelementptr i8, ptr %scevgep1155, i64 -48
  %.5938.1 = load double, ptr %scevgep1156, align 8
  %scevgep1141 = getelementptr i8, ptr %lsr.iv1133, i64 -48
  store double %.5938.1, ptr %scevgep1141, align 8
  %scevgep1151 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1152 = getelementptr i8, ptr %scevgep1151, i64 -40
  %.5938.2 = load double, ptr %scevgep1152, align 8
  %scevgep1139 = getelementptr i8, ptr %lsr.iv1133, i64 -40
  store double %.5938.2, ptr %scevgep1139, align 8
  %scevgep1149 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1150 = getelementptr i8, ptr %scevgep1149, i64 -32
  %.5938.3 = load double, ptr %scevgep1150, align 8
  %scevgep1138 = getelementptr i8, ptr %lsr.iv1133, i64 -32
  store double %.5938.3, ptr %scevgep1138, align 8
  %scevgep1147 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1148 = getelementptr i8, ptr %scevgep1147, i64 -24
  %.5938.4 = load double, ptr %scevgep1148, align 8
  %scevgep1137 = getelementptr i8, ptr %lsr.iv1133, i64 -24
  store double %.5938.4, ptr %scevgep1137, align 8
  %scevgep1145 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1146 = getelementptr i8, ptr %scevgep1145, i64 -16
  %.5938.5 = load double, ptr %scevgep1146, align 8
  %scevgep1136 = getelementptr i8, ptr %lsr.iv1133, i64 -16
  store double %.5938.5, ptr %scevgep1136, align 8
  %scevgep1143 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %scevgep1144 = getelementptr i8, ptr %scevgep1143, i64 -8
  %.5938.6 = load double, ptr %scevgep1144, align 8
  %scevgep1135 = getelementptr i8, ptr %lsr.iv1133, i64 -8
  store double %.5938.6, ptr %scevgep1135, align 8
  %scevgep1142 = getelementptr i8, ptr %lsr.iv1133, i64 %.2189.idx
  %.5938.7 = load double, ptr %scevgep1142, align 8
  store double %.5938.7, ptr %lsr.iv1133, align 8
  %lsr.iv.next1130 = add i64 %lsr.iv1129, -8
  %scevgep1134 = getelementptr i8, ptr %lsr.iv1133, i64 64
  %exitcond4994.not.7 = icmp eq i64 %lsr.iv.next1130, 0
  br i1 %exitcond4994.not.7, label %B3208, label %B3174, !llvm.loop !13

B3208:                                            ; preds = %B3174, %B3174.prol.loopexit, %middle.block, %vec.epilog.middle.block, %B3062.endif, %B3120
  %43 = icmp eq ptr %arg.post.2, null
  %.6003 = add nuw nsw i64 %steps.2.0, 1
  %sunkaddr1223 = getelementptr i8, ptr %arg.ist.4, i64 40
  %.6038 = load i64, ptr %sunkaddr1223, align 8
  %.6039 = add nsw i64 %.6038, 1
  store i64 %.6039, ptr %sunkaddr1223, align 8
  br i1 %43, label %B3208.if, label %B3208.else, !prof !0

B3306:                                            ; preds = %B3208.endif
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B3314:                                            ; preds = %B3208.endif
  %.6303.not = icmp eq i64 %.6082.0, 0
  br i1 %.6303.not, label %B3356, label %B3336

B3336:                                            ; preds = %B3314
  %sunkaddr1224 = getelementptr i8, ptr %arg.ist.4, i64 72
  store i64 1, ptr %sunkaddr1224, align 8
  br label %B3356

B3356:                                            ; preds = %B3336, %B3314
  %44 = icmp eq i64 %.381, 0
  br i1 %44, label %B3734, label %B3360

B3360:                                            ; preds = %B3356
  %sunkaddr1225 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.6367 = load i64, ptr %sunkaddr1225, align 8
  %.6369 = icmp slt i64 %.6367, %arg.t_eval.2
  br i1 %.6369, label %B3394, label %B3870

B3394:                                            ; preds = %B3360
  %.6414 = icmp slt i64 %.6367, 0
  %.6415 = select i1 %.6414, i64 %arg.t_eval.5.0, i64 0
  %45 = getelementptr double, ptr %arg.t_eval.4, i64 %.6367
  %.6429 = getelementptr double, ptr %45, i64 %.6415
  %.6430 = load double, ptr %.6429, align 8
  %.6432 = fcmp ugt double %.6430, %t_new.8.14661
  br i1 %.6432, label %B3870, label %B3440.preheader

B3440.preheader:                                  ; preds = %B3394
  %sunkaddr1226 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.6466.pre = load i64, ptr %sunkaddr1226, align 8
  br label %B3440

B3440:                                            ; preds = %B3440.preheader, %B3686
  %.6466 = phi i64 [ %.6466.pre, %B3440.preheader ], [ %.6779, %B3686 ]
  %46 = icmp eq ptr %arg.to_ambient.2, null
  %.6485 = icmp slt i64 %.6466, 0
  %.6486 = select i1 %.6485, i64 %arg.Y_out.5.0, i64 0
  %.6487 = add i64 %.6486, %.6466
  %.6504 = mul i64 %.6487, %arg.Y_out.5.1
  %.6506 = getelementptr double, ptr %arg.Y_out.4, i64 %.6504
  %.6534.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.3.insert, ptr %.6506, 4
  %.6534.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6534.fca.4.insert, i64 %arg.Y_out.5.1, 5, 0
  %.6534.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6534.fca.5.0.insert, i64 %arg.Y_out.6.1, 6, 0
  call void @NRT_incref(ptr %arg.Y_out.0)
  br i1 %46, label %B3440.if, label %B3440.else, !prof !0

B3686:                                            ; preds = %B3440.endif
  %.6947 = icmp slt i64 %.6839, -1
  %.6948 = select i1 %.6947, i64 %arg.t_eval.5.0, i64 0
  %47 = getelementptr double, ptr %arg.t_eval.4, i64 %.6840
  %.6962 = getelementptr double, ptr %47, i64 %.6948
  %.6963 = load double, ptr %.6962, align 8
  %.6965 = fcmp ugt double %.6963, %t_new.8.14661
  br i1 %.6965, label %B3870, label %B3440

B3734:                                            ; preds = %B3356
  %48 = icmp eq ptr %arg.to_ambient.2, null
  %sunkaddr1227 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.7002 = load i64, ptr %sunkaddr1227, align 8
  %.7021 = icmp slt i64 %.7002, 0
  %.7022 = select i1 %.7021, i64 %arg.Y_out.5.0, i64 0
  %.7023 = add i64 %.7022, %.7002
  %.7040 = mul i64 %.7023, %arg.Y_out.5.1
  %.7042 = getelementptr double, ptr %arg.Y_out.4, i64 %.7040
  %.7070.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.3.insert, ptr %.7042, 4
  %.7070.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7070.fca.4.insert, i64 %arg.Y_out.5.1, 5, 0
  %.7070.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7070.fca.5.0.insert, i64 %arg.Y_out.6.1, 6, 0
  call void @NRT_incref(ptr %arg.Y_out.0)
  br i1 %48, label %B3734.if, label %B3734.else, !prof !0

B3870:                                            ; preds = %B3686, %B3440.endif, %B3360, %B3394, %B3734.endif
  %49 = icmp eq ptr %arg.invariants.2, null
  br i1 %49, label %B3870.if, label %B3870.else, !prof !0

B3954:                                            ; preds = %B0.endif.i
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

B3970:                                            ; preds = %B0.endif.i
  %.131.i = fsub double %.117.i, %.7407
  %.132.i = call double @llvm.fabs.f64(double %.131.i)
  %.142.i = fdiv double %.132.i, %.7407
  %.205.i = load double, ptr %arg.mon.4, align 8, !noalias !14
  %.207.i = call double @llvm.fabs.f64(double %.59.i)
  %.12.i.i210 = fcmp ogt double %.207.i, %.205.i
  %.13.i.i211 = select i1 %.12.i.i210, double %.207.i, double %.205.i
  store double %.13.i.i211, ptr %arg.mon.4, align 8, !noalias !14
  %sunkaddr1228 = getelementptr i8, ptr %arg.mon.4, i64 8
  %.297.i = load double, ptr %sunkaddr1228, align 8, !noalias !14
  %.299.i = call double @llvm.fabs.f64(double %.88.i)
  %.12.i1.i212 = fcmp ogt double %.299.i, %.297.i
  %.13.i2.i = select i1 %.12.i1.i212, double %.299.i, double %.297.i
  store double %.13.i2.i, ptr %sunkaddr1228, align 8, !noalias !14
  %sunkaddr1229 = getelementptr i8, ptr %arg.mon.4, i64 16
  %.389.i = load double, ptr %sunkaddr1229, align 8, !noalias !14
  %.12.i3.i213 = fcmp ogt double %.142.i, %.389.i
  %.13.i4.i214 = select i1 %.12.i3.i213, double %.142.i, double %.389.i
  store double %.13.i4.i214, ptr %sunkaddr1229, align 8, !noalias !14
  %.7582 = icmp eq i64 %.6082.0, 3
  br i1 %.7582, label %B3992, label %B276

B3992:                                            ; preds = %B3970
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.t_eval.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.mon.0)
  call void @NRT_decref(ptr %arg.log.0)
  call void @NRT_decref(ptr %arg.ipar.0)
  call void @NRT_decref(ptr %arg.inv.0)
  call void @NRT_decref(ptr %arg.Y_out.0)
  call void @NRT_decref(ptr %arg.T_out.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.F.0)
  br label %B4012

common.ret:                                       ; preds = %B3870.endif.endif.if.if, %B3870.else.if.if, %B3870.if.if.if, %B3734.else.if.if, %B3734.if.if.if, %B3440.else.if.if, %B3440.if.if.if, %B3208.else.if.if, %B3208.if.if.if, %B2902.if.if, %B2554.endif.endif.else.if.if, %B2554.endif.endif.if.if.if, %B2554.endif.if.if, %B2554.if, %B2304.if.if, %B1796.if.if, %B1440.if.if, %B1190.else.if.if, %B1190.if.if.if, %B1008.endif.if.if, %B1008.else.if.if, %B1008.if.if.if, %B860.if.if, %B500.else.if.if, %B500.if.if.endif.if, %B500.if.if.if, %B4012
  %common.ret.op = phi i32 [ 0, %B4012 ], [ 1, %B500.if.if.if ], [ 1, %B500.if.if.endif.if ], [ %.1339, %B500.else.if.if ], [ 1, %B3870.endif.endif.if.if ], [ %.7354, %B3870.else.if.if ], [ %.1791, %B860.if.if ], [ 1, %B1008.if.if.if ], [ %.2283, %B1008.else.if.if ], [ %.2533, %B1008.endif.if.if ], [ 1, %B1190.if.if.if ], [ %.2752, %B1190.else.if.if ], [ %.3305, %B1440.if.if ], [ 1, %B3870.if.if.if ], [ %.3638.lcssa, %B1796.if.if ], [ %.7139, %B3734.else.if.if ], [ %.4326, %B2304.if.if ], [ 1, %B2554.if ], [ %.4746, %B2554.endif.if.if ], [ 1, %B2554.endif.endif.if.if.if ], [ %.4932, %B2554.endif.endif.else.if.if ], [ %.5489, %B2902.if.if ], [ 1, %B3208.if.if.if ], [ %.6139, %B3208.else.if.if ], [ 1, %B3440.if.if.if ], [ %.6603, %B3440.else.if.if ], [ 1, %B3734.if.if.if ]
  ret i32 %common.ret.op

B4012:                                            ; preds = %B1388, %B1340, %B3992, %B3954, %B3306, %B2192, %B986, %B956, %B608, %B482, %B404, %B340, %B288
  %t.3.0 = phi double [ %t.2.0, %B288 ], [ %t.2.0, %B340 ], [ %t.2.0, %B482 ], [ %t.2.0, %B608 ], [ %t.2.0, %B956 ], [ %t.2.0, %B986 ], [ %t_new.8.14661, %B3306 ], [ %t_new.8.14661, %B3992 ], [ %t_new.8.14661, %B3954 ], [ %t.2.0, %B404 ], [ %t.2.0, %B2192 ], [ %t.2.0, %B1340 ], [ %t.2.0, %B1388 ]
  %status.15.0 = phi i64 [ 1, %B288 ], [ 0, %B340 ], [ 2, %B482 ], [ -2, %B608 ], [ -2, %B956 ], [ -1, %B986 ], [ %.6082.0, %B3306 ], [ 3, %B3992 ], [ -4, %B3954 ], [ 2, %B404 ], [ %status.14.2.ph, %B2192 ], [ -1, %B1340 ], [ -2, %B1388 ]
  store double %t.3.0, ptr %arg.st.4, align 8
  call void @NRT_decref(ptr %arg.st.0)
  %.7810 = getelementptr i8, ptr %arg.ist.4, i64 32
  store i64 %status.15.0, ptr %.7810, align 8
  call void @NRT_decref(ptr %arg.ist.0)
  store i64 %status.15.0, ptr %retptr, align 8
  br label %common.ret

B500.if:                                          ; preds = %B500
  %50 = icmp eq ptr %arg.cap.0, null
  br i1 %50, label %B500.if.if, label %B500.if.endif, !prof !0

B500.else:                                        ; preds = %B500
  store double 0.000000e+00, ptr %.1329, align 8
  %.1339 = call i32 %arg.cap.2(ptr nonnull %.1329, ptr nonnull %excinfo.1, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0)
  %.1349 = load double, ptr %.1329, align 8
  switch i32 %.1339, label %B500.else.if.if [
    i32 -2, label %B500.endif
    i32 0, label %B500.endif
  ], !prof !4

B500.endif:                                       ; preds = %B500.else, %B500.else, %B500.if.endif
  %.1274.0 = phi double [ %.1325, %B500.if.endif ], [ %.1349, %B500.else ], [ %.1349, %B500.else ]
  %.1375 = call double @numba_nextafter(double %t.2.0, double 0x7FF0000000000000)
  %.1381 = fsub double %.1375, %t.2.0
  %.1382 = fmul double %.1381, 1.000000e+01
  %.1384 = fcmp olt double %.1274.0, %.1382
  br i1 %.1384, label %B608, label %B626

B500.if.if:                                       ; preds = %B500.if
  %.1282 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE, align 8
  %.1283 = icmp eq ptr %.1282, null
  br i1 %.1283, label %B500.if.if.if, label %B500.if.if.endif, !prof !0

B500.if.endif:                                    ; preds = %B500.if, %B500.if.if.endif.endif
  %fptr_of_cap.0 = phi ptr [ %.1315, %B500.if.if.endif.endif ], [ %arg.cap.0, %B500.if ]
  %.1325 = call double %fptr_of_cap.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert)
  br label %B500.endif

B500.if.if.if:                                    ; preds = %B500.if.if
  store ptr @.const.picklebuf.1c6fb341d2c5b01f06081782f6c0835b91b257d2, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B500.if.if.endif:                                 ; preds = %B500.if.if
  call void @numba_gil_ensure(ptr nonnull %.1294)
  %.1297 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.1298 = call ptr @PyObject_GetAttrString(ptr %.1297, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.1297)
  %.1306 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a, i32 495, ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.sha1)
  %.1307 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.1298, ptr %arg.cap.1, ptr %.1306, ptr null)
  %.1308 = icmp eq ptr %.1307, null
  br i1 %.1308, label %B500.if.if.endif.if, label %B500.if.if.endif.endif, !prof !0

B500.if.if.endif.if:                              ; preds = %B500.if.if.endif
  store ptr @.const.picklebuf.4018623931e8e32c18b820afa637cf5cbf1f5535, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B500.if.if.endif.endif:                           ; preds = %B500.if.if.endif
  %.1315 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.1307)
  call void @Py_DecRef(ptr nonnull %.1307)
  call void @numba_gil_release(ptr nonnull %.1294)
  br label %B500.if.endif

B500.else.if.if:                                  ; preds = %B500.else
  %.1347 = icmp sgt i32 %.1339, 0
  %.1340 = load ptr, ptr %excinfo.1, align 8
  %.1348 = select i1 %.1347, ptr %.1340, ptr undef
  store ptr %.1348, ptr %excinfo, align 8
  br label %common.ret

B756.endif:                                       ; preds = %B734
  %sunkaddr1230 = getelementptr i8, ptr %arg.st.4, i64 24
  %.1697 = load double, ptr %sunkaddr1230, align 8
  %.12.i187 = fcmp olt double %.1274.0, %.1697
  %.13.i188 = select i1 %.12.i187, double %.1274.0, double %.1697
  %.1733 = fmul double %.13.i188, 0x3FF000000044B830
  %.1736 = fsub double %t_next.2.1, %t.2.0
  %.1737 = fcmp oge double %.1733, %.1736
  %.1761 = fadd double %t.2.0, %.13.i188
  %h.6.1 = select i1 %.1737, double %.1736, double %.13.i188
  %t_new.9.1 = select i1 %.1737, double %t_next.2.1, double %.1761
  store double 0.000000e+00, ptr %.1775, align 8
  %.1791 = call i32 @_ZN6charts7solvers2rk8rk4_stepB3v74B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMVC_2fAwA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.1775, ptr nonnull %excinfo.4, ptr %arg.rhs.0, ptr %arg.rhs.1, ptr %arg.rhs.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %h.6.1, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0)
  %.1801 = load double, ptr %.1775, align 8
  %cond = icmp eq i32 %.1791, 0
  br i1 %cond, label %B860.endif, label %B860.if.if, !prof !1

B860.endif:                                       ; preds = %B756.endif
  %sunkaddr1231 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.1843 = load i64, ptr %sunkaddr1231, align 8
  %.1844 = add nsw i64 %.1843, 4
  store i64 %.1844, ptr %sunkaddr1231, align 8
  %.1876 = fcmp olt double %.1801, 0.000000e+00
  br i1 %.1876, label %B956, label %B974

B860.if.if:                                       ; preds = %B756.endif
  %.1799 = icmp sgt i32 %.1791, 0
  %.1792 = load ptr, ptr %excinfo.4, align 8
  %.1800 = select i1 %.1799, ptr %.1792, ptr undef
  store ptr %.1800, ptr %excinfo, align 8
  br label %common.ret

B1008.if:                                         ; preds = %B1008
  %51 = icmp eq ptr %arg.rhs.0, null
  br i1 %51, label %B1008.if.if, label %B1008.if.endif, !prof !0

B1008.else:                                       ; preds = %B1008
  store double 0.000000e+00, ptr %.2273, align 8
  %.2283 = call i32 %arg.rhs.2(ptr nonnull %.2273, ptr nonnull %excinfo.5, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.2189, i64 %arg.K.5.1, i64 %arg.K.6.1)
  switch i32 %.2283, label %B1008.else.if.if [
    i32 -2, label %B1008.endif
    i32 0, label %B1008.endif
  ], !prof !4

B1008.endif:                                      ; preds = %B1008.else, %B1008.else, %B1008.if.endif
  %sunkaddr1232 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.2338 = load i64, ptr %sunkaddr1232, align 8
  %.2339 = add nsw i64 %.2338, 1
  store i64 %.2339, ptr %sunkaddr1232, align 8
  call void @NRT_incref(ptr %arg.K.0)
  store ptr null, ptr %.2517, align 8
  %.2533 = call i32 @_ZN6charts7solvers2rk13hermite_denseB3v82B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE(ptr nonnull %.2517, ptr nonnull %excinfo.6, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %h.6.1, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.1, i64 %arg.K.6.1, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.2189, i64 %arg.K.5.1, i64 %arg.K.6.1, ptr %arg.F.0, ptr %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1)
  switch i32 %.2533, label %B1008.endif.if.if [
    i32 -2, label %B2898.thread4678
    i32 0, label %B2898.thread4678
  ], !prof !4

B1008.if.if:                                      ; preds = %B1008.if
  call void @numba_gil_ensure(ptr nonnull %.2238)
  %.2241 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.2242 = call ptr @PyObject_GetAttrString(ptr %.2241, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.2241)
  %.2250 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1)
  %.2251 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.2242, ptr %arg.rhs.1, ptr %.2250, ptr null)
  %.2252 = icmp eq ptr %.2251, null
  br i1 %.2252, label %B1008.if.if.if, label %B1008.if.if.endif, !prof !0

B1008.if.endif:                                   ; preds = %B1008.if, %B1008.if.if.endif
  %fptr_of_rhs.0 = phi ptr [ %.2259, %B1008.if.if.endif ], [ %arg.rhs.0, %B1008.if ]
  %.2269 = call double %fptr_of_rhs.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1774.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2217.fca.6.0.insert)
  br label %B1008.endif

B1008.if.if.if:                                   ; preds = %B1008.if.if
  store ptr @.const.picklebuf.6412c1d038c4ddd627f0e96e9f665bdf17f85c41, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B1008.if.if.endif:                                ; preds = %B1008.if.if
  %.2259 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.2251)
  call void @Py_DecRef(ptr nonnull %.2251)
  call void @numba_gil_release(ptr nonnull %.2238)
  br label %B1008.if.endif

B1008.else.if.if:                                 ; preds = %B1008.else
  %.2291 = icmp sgt i32 %.2283, 0
  %.2284 = load ptr, ptr %excinfo.5, align 8
  %.2292 = select i1 %.2291, ptr %.2284, ptr undef
  store ptr %.2292, ptr %excinfo, align 8
  br label %common.ret

B2898.thread4678:                                 ; preds = %B1008.endif, %B1008.endif
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.K.0)
  br label %B2902

B1008.endif.if.if:                                ; preds = %B1008.endif
  store ptr null, ptr %excinfo, align 8
  br label %common.ret

B1190.if:                                         ; preds = %B1190
  %52 = icmp eq ptr %arg.rhs.0, null
  br i1 %52, label %B1190.if.if, label %B1190.if.endif, !prof !0

B1190.else:                                       ; preds = %B1190
  store double 0.000000e+00, ptr %.2742, align 8
  %.2752 = call i32 %arg.rhs.2(ptr nonnull %.2742, ptr nonnull %excinfo.7, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.1, i64 %arg.K.6.1)
  %.2762 = load double, ptr %.2742, align 8
  switch i32 %.2752, label %B1190.else.if.if [
    i32 -2, label %B1190.endif
    i32 0, label %B1190.endif
  ], !prof !4

B1190.endif:                                      ; preds = %B1190.else, %B1190.else, %B1190.if.endif
  %.2699.0 = phi double [ %.2738, %B1190.if.endif ], [ %.2762, %B1190.else ], [ %.2762, %B1190.else ]
  call void @NRT_decref(ptr %arg.K.0)
  %sunkaddr1233 = getelementptr i8, ptr %arg.st.4, i64 64
  store double %.2699.0, ptr %sunkaddr1233, align 8
  %sunkaddr1234 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.2837 = load i64, ptr %sunkaddr1234, align 8
  %.2838 = add nsw i64 %.2837, 1
  store i64 %.2838, ptr %sunkaddr1234, align 8
  %sunkaddr1235 = getelementptr i8, ptr %arg.ist.4, i64 72
  store i64 0, ptr %sunkaddr1235, align 8
  br label %B1306

B1190.if.if:                                      ; preds = %B1190.if
  call void @numba_gil_ensure(ptr nonnull %.2707)
  %.2710 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.2711 = call ptr @PyObject_GetAttrString(ptr %.2710, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.2710)
  %.2719 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1)
  %.2720 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.2711, ptr %arg.rhs.1, ptr %.2719, ptr null)
  %.2721 = icmp eq ptr %.2720, null
  br i1 %.2721, label %B1190.if.if.if, label %B1190.if.if.endif, !prof !0

B1190.if.endif:                                   ; preds = %B1190.if, %B1190.if.if.endif
  %fptr_of_rhs.1.0 = phi ptr [ %.2728, %B1190.if.if.endif ], [ %arg.rhs.0, %B1190.if ]
  %.2738 = call double %fptr_of_rhs.1.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.2686.fca.6.0.insert)
  br label %B1190.endif

B1190.if.if.if:                                   ; preds = %B1190.if.if
  store ptr @.const.picklebuf.f1e7bd29a4ad75134f039f453b107cce992df92e, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B1190.if.if.endif:                                ; preds = %B1190.if.if
  %.2728 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.2720)
  call void @Py_DecRef(ptr nonnull %.2720)
  call void @numba_gil_release(ptr nonnull %.2707)
  br label %B1190.if.endif

B1190.else.if.if:                                 ; preds = %B1190.else
  %.2760 = icmp sgt i32 %.2752, 0
  %.2753 = load ptr, ptr %excinfo.7, align 8
  %.2761 = select i1 %.2760, ptr %.2753, ptr undef
  store ptr %.2761, ptr %excinfo, align 8
  br label %common.ret

B1440.endif:                                      ; preds = %B1440
  %.3315 = load double, ptr %.3291, align 8
  call void @NRT_decref(ptr %arg.K.0)
  call void @NRT_decref(ptr %arg.K.0)
  %sunkaddr1236 = getelementptr i8, ptr %arg.st.4, i64 8
  store double %.3315, ptr %sunkaddr1236, align 8
  %sunkaddr1237 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.3390 = load i64, ptr %sunkaddr1237, align 8
  %.3391 = add nsw i64 %.3390, 1
  store i64 %.3391, ptr %sunkaddr1237, align 8
  %.3464.pre = load double, ptr %sunkaddr1236, align 8
  br label %B1648.preheader

B1440.if.if:                                      ; preds = %B1440
  %.3313 = icmp sgt i32 %.3305, 0
  %.3306 = load ptr, ptr %excinfo.8, align 8
  %.3314 = select i1 %.3313, ptr %.3306, ptr undef
  store ptr %.3314, ptr %excinfo, align 8
  br label %common.ret

B1796.endif:                                      ; preds = %B1752
  %sunkaddr1238 = getelementptr i8, ptr %arg.ist.4, i64 56
  %.3701 = load i64, ptr %sunkaddr1238, align 8
  %.3702 = add nsw i64 %.3701, 12
  store i64 %.3702, ptr %sunkaddr1238, align 8
  %.3734 = fcmp uge double %.3648.fca.1.load, 0.000000e+00
  %.3737 = fsub double %.3648.fca.0.load, %.3648.fca.0.load
  %.3738 = fcmp ord double %.3737, 0.000000e+00
  %or.cond = select i1 %.3734, i1 %.3738, i1 false
  br i1 %or.cond, label %B2010, label %B1942

B1796.if.if:                                      ; preds = %B1752.peel, %B1752
  %.3638.lcssa = phi i32 [ %.3638, %B1752 ], [ %.3638.peel, %B1752.peel ]
  %.3646 = icmp sgt i32 %.3638.lcssa, 0
  %.3639 = load ptr, ptr %excinfo.10, align 8
  %.3647 = select i1 %.3646, ptr %.3639, ptr undef
  store ptr %.3647, ptr %excinfo, align 8
  br label %common.ret

B2304.if.if:                                      ; preds = %B2304
  %.4334 = icmp sgt i32 %.4326, 0
  %.4327 = load ptr, ptr %excinfo.12, align 8
  %.4335 = select i1 %.4334, ptr %.4327, ptr undef
  store ptr %.4335, ptr %excinfo, align 8
  br label %common.ret

B2554.if:                                         ; preds = %B2554.preheader
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B2554.endif.endif:                                ; preds = %B2554, %B2554
  %53 = icmp eq ptr %arg.to_ambient.2, null
  %sunkaddr1239 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.4795 = load i64, ptr %sunkaddr1239, align 8
  %.4814 = icmp slt i64 %.4795, 0
  %.4815 = select i1 %.4814, i64 %arg.Y_out.5.0, i64 0
  %.4816 = add i64 %.4815, %.4795
  %.4833 = mul i64 %.4816, %arg.Y_out.5.1
  %.4835 = getelementptr double, ptr %arg.Y_out.4, i64 %.4833
  %.4863.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.3.insert, ptr %.4835, 4
  %.4863.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.4.insert, i64 %arg.Y_out.5.1, 5, 0
  %.4863.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.5.0.insert, i64 %arg.Y_out.6.1, 6, 0
  call void @NRT_incref(ptr %arg.Y_out.0)
  br i1 %53, label %B2554.endif.endif.if, label %B2554.endif.endif.else, !prof !0

B2554.endif.if.if:                                ; preds = %B2554
  store ptr null, ptr %excinfo, align 8
  br label %common.ret

B2554.endif.endif.if:                             ; preds = %B2554.endif.endif
  %54 = icmp eq ptr %arg.to_ambient.0, null
  br i1 %54, label %B2554.endif.endif.if.if, label %B2554.endif.endif.if.endif, !prof !0

B2554.endif.endif.else:                           ; preds = %B2554.endif.endif
  store double 0.000000e+00, ptr %.4920, align 8
  %.4932 = call i32 %arg.to_ambient.2(ptr nonnull %.4920, ptr nonnull %excinfo.14, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, ptr %arg.Y_out.0, ptr %arg.Y_out.1, i64 %arg.Y_out.5.1, i64 %arg.Y_out.3, ptr %.4835, i64 %arg.Y_out.5.1, i64 %arg.Y_out.6.1)
  switch i32 %.4932, label %B2554.endif.endif.else.if.if [
    i32 -2, label %B2554.endif.endif.endif
    i32 0, label %B2554.endif.endif.endif
  ], !prof !4

B2554.endif.endif.endif:                          ; preds = %B2554.endif.endif.else, %B2554.endif.endif.else, %B2554.endif.endif.if.endif
  call void @NRT_decref(ptr %arg.Y_out.0)
  %sunkaddr1240 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.4987 = load i64, ptr %sunkaddr1240, align 8
  %.5001 = icmp slt i64 %.4987, 0
  %.5002 = select i1 %.5001, i64 %arg.T_out.5.0, i64 0
  %55 = getelementptr double, ptr %arg.T_out.4, i64 %.4987
  %.5016 = getelementptr double, ptr %55, i64 %.5002
  store double %.4718, ptr %.5016, align 8
  %.5047 = load i64, ptr %sunkaddr1240, align 8
  %.5048 = add nsw i64 %.5047, 1
  store i64 %.5048, ptr %sunkaddr1240, align 8
  %sunkaddr1241 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.5108 = load i64, ptr %sunkaddr1241, align 8
  %.5109 = add nsw i64 %.5108, 1
  store i64 %.5109, ptr %sunkaddr1241, align 8
  %.5171 = icmp slt i64 %.5109, %arg.t_eval.2
  br i1 %.5171, label %B2852, label %B2898

B2554.endif.endif.if.if:                          ; preds = %B2554.endif.endif.if
  call void @numba_gil_ensure(ptr nonnull %.4885)
  %.4888 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.4889 = call ptr @PyObject_GetAttrString(ptr %.4888, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.4888)
  %.4897 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1)
  %.4898 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.4889, ptr %arg.to_ambient.1, ptr %.4897, ptr null)
  %.4899 = icmp eq ptr %.4898, null
  br i1 %.4899, label %B2554.endif.endif.if.if.if, label %B2554.endif.endif.if.if.endif, !prof !0

B2554.endif.endif.if.endif:                       ; preds = %B2554.endif.endif.if, %B2554.endif.endif.if.if.endif
  %fptr_of_to_ambient.0 = phi ptr [ %.4906, %B2554.endif.endif.if.if.endif ], [ %arg.to_ambient.0, %B2554.endif.endif.if ]
  %.4916 = call double %fptr_of_to_ambient.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4733.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.4863.fca.6.0.insert)
  br label %B2554.endif.endif.endif

B2554.endif.endif.if.if.if:                       ; preds = %B2554.endif.endif.if.if
  store ptr @.const.picklebuf.91aaf861f3f5a4f952b411fb74b5ebbdc030024d, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B2554.endif.endif.if.if.endif:                    ; preds = %B2554.endif.endif.if.if
  %.4906 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.4898)
  call void @Py_DecRef(ptr nonnull %.4898)
  call void @numba_gil_release(ptr nonnull %.4885)
  br label %B2554.endif.endif.if.endif

B2554.endif.endif.else.if.if:                     ; preds = %B2554.endif.endif.else
  %.4940 = icmp sgt i32 %.4932, 0
  %.4933 = load ptr, ptr %excinfo.14, align 8
  %.4941 = select i1 %.4940, ptr %.4933, ptr undef
  store ptr %.4941, ptr %excinfo, align 8
  br label %common.ret

B2902.endif:                                      ; preds = %B2902, %B2902
  call void @NRT_decref(ptr %arg.ISeg.0)
  call void @NRT_decref(ptr %arg.Seg.0)
  %sunkaddr1242 = getelementptr i8, ptr %arg.ist.4, i64 88
  %.5546 = load i64, ptr %sunkaddr1242, align 8
  %.5547 = add nsw i64 %.5546, 1
  store i64 %.5547, ptr %sunkaddr1242, align 8
  br label %B3062.endif

B2902.if.if:                                      ; preds = %B2902
  store ptr null, ptr %excinfo, align 8
  br label %common.ret

B3062.endif:                                      ; preds = %B2220, %B1004, %B2898, %B2902.endif
  %t_new.8.14661 = phi double [ %t_new.10.5.le, %B2898 ], [ %t_new.8.14705, %B2902.endif ], [ %t_new.9.1, %B1004 ], [ %t_new.10.5.le, %B2220 ]
  %56 = icmp sgt i64 %arg.y.2, 0
  br i1 %56, label %iter.check759, label %B3208

iter.check759:                                    ; preds = %B3062.endif
  br i1 %or.cond789, label %B3094.preheader, label %vector.main.loop.iter.check761

vector.main.loop.iter.check761:                   ; preds = %iter.check759
  %57 = icmp ult i64 %arg.y.2, 32
  br i1 %57, label %vec.epilog.ph778, label %vector.body765.preheader

vector.body765.preheader:                         ; preds = %vector.main.loop.iter.check761
  br label %vector.body765

vector.body765:                                   ; preds = %vector.body765.preheader, %vector.body765
  %index766 = phi i64 [ %index.next771, %vector.body765 ], [ 0, %vector.body765.preheader ]
  %sunkaddr1243 = mul i64 %index766, 8
  %sunkaddr1244 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1243
  %wide.load767 = load <8 x double>, ptr %sunkaddr1244, align 8
  %sunkaddr1245 = mul i64 %index766, 8
  %sunkaddr1246 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1245
  %sunkaddr1247 = getelementptr i8, ptr %sunkaddr1246, i64 64
  %wide.load768 = load <8 x double>, ptr %sunkaddr1247, align 8
  %sunkaddr1248 = mul i64 %index766, 8
  %sunkaddr1249 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1248
  %sunkaddr1250 = getelementptr i8, ptr %sunkaddr1249, i64 128
  %wide.load769 = load <8 x double>, ptr %sunkaddr1250, align 8
  %sunkaddr1251 = mul i64 %index766, 8
  %sunkaddr1252 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1251
  %sunkaddr1253 = getelementptr i8, ptr %sunkaddr1252, i64 192
  %wide.load770 = load <8 x double>, ptr %sunkaddr1253, align 8
  %sunkaddr1254 = mul i64 %index766, 8
  %sunkaddr1255 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1254
  store <8 x double> %wide.load767, ptr %sunkaddr1255, align 8
  %sunkaddr1256 = mul i64 %index766, 8
  %sunkaddr1257 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1256
  %sunkaddr1258 = getelementptr i8, ptr %sunkaddr1257, i64 64
  store <8 x double> %wide.load768, ptr %sunkaddr1258, align 8
  %sunkaddr1259 = mul i64 %index766, 8
  %sunkaddr1260 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1259
  %sunkaddr1261 = getelementptr i8, ptr %sunkaddr1260, i64 128
  store <8 x double> %wide.load769, ptr %sunkaddr1261, align 8
  %sunkaddr1262 = mul i64 %index766, 8
  %sunkaddr1263 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1262
  %sunkaddr1264 = getelementptr i8, ptr %sunkaddr1263, i64 192
  store <8 x double> %wide.load770, ptr %sunkaddr1264, align 8
  %index.next771 = add nuw i64 %index766, 32
  %58 = icmp eq i64 %n.vec764, %index.next771
  br i1 %58, label %middle.block772, label %vector.body765, !llvm.loop !19

middle.block772:                                  ; preds = %vector.body765
  %59 = icmp eq i64 %arg.y.2, %n.vec764
  br i1 %59, label %B3120, label %vec.epilog.iter.check776

vec.epilog.iter.check776:                         ; preds = %middle.block772
  %60 = and i64 %arg.y.2, 28
  %61 = icmp eq i64 %60, 0
  br i1 %61, label %B3094.preheader, label %vec.epilog.ph778, !prof !9

vec.epilog.ph778:                                 ; preds = %vector.main.loop.iter.check761, %vec.epilog.iter.check776
  %vec.epilog.resume.val774 = phi i64 [ %n.vec764, %vec.epilog.iter.check776 ], [ 0, %vector.main.loop.iter.check761 ]
  br label %vec.epilog.vector.body781

vec.epilog.vector.body781:                        ; preds = %vec.epilog.vector.body781, %vec.epilog.ph778
  %index782 = phi i64 [ %vec.epilog.resume.val774, %vec.epilog.ph778 ], [ %index.next784, %vec.epilog.vector.body781 ]
  %62 = shl i64 %index782, 3
  %scevgep1067 = getelementptr i8, ptr %arg.ynew.4, i64 %62
  %wide.load783 = load <4 x double>, ptr %scevgep1067, align 8
  %63 = shl i64 %index782, 3
  %scevgep1066 = getelementptr i8, ptr %arg.y.4, i64 %63
  store <4 x double> %wide.load783, ptr %scevgep1066, align 8
  %index.next784 = add nuw i64 %index782, 4
  %64 = icmp eq i64 %n.vec780, %index.next784
  br i1 %64, label %vec.epilog.middle.block785, label %vec.epilog.vector.body781, !llvm.loop !20

vec.epilog.middle.block785:                       ; preds = %vec.epilog.vector.body781
  %65 = icmp eq i64 %arg.y.2, %n.vec780
  br i1 %65, label %B3120, label %B3094.preheader

B3094.preheader:                                  ; preds = %iter.check759, %vec.epilog.iter.check776, %vec.epilog.middle.block785
  %.566748564858.ph = phi i64 [ 0, %iter.check759 ], [ %n.vec764, %vec.epilog.iter.check776 ], [ %n.vec780, %vec.epilog.middle.block785 ]
  %66 = sub nsw i64 %arg.y.2, %.566748564858.ph
  %xtraiter = and i64 %66, 7
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B3094.prol.loopexit, label %B3094.prol.preheader

B3094.prol.preheader:                             ; preds = %B3094.preheader
  br label %B3094.prol

B3094.prol:                                       ; preds = %B3094.prol.preheader, %B3094.prol
  %lsr.iv = phi i64 [ %xtraiter, %B3094.prol.preheader ], [ %lsr.iv.next, %B3094.prol ]
  %.566748564858.prol = phi i64 [ %.5674.prol, %B3094.prol ], [ %.566748564858.ph, %B3094.prol.preheader ]
  %.5674.prol = add nuw i64 %.566748564858.prol, 1
  %67 = shl i64 %.566748564858.prol, 3
  %scevgep1069 = getelementptr i8, ptr %arg.ynew.4, i64 %67
  %.5728.prol = load double, ptr %scevgep1069, align 8
  %68 = shl i64 %.566748564858.prol, 3
  %scevgep1068 = getelementptr i8, ptr %arg.y.4, i64 %68
  store double %.5728.prol, ptr %scevgep1068, align 8
  %lsr.iv.next = add nsw i64 %lsr.iv, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next, 0
  br i1 %prol.iter.cmp.not, label %B3094.prol.loopexit, label %B3094.prol, !llvm.loop !21

B3094.prol.loopexit:                              ; preds = %B3094.prol, %B3094.preheader
  %.566748564858.unr = phi i64 [ %.566748564858.ph, %B3094.preheader ], [ %.5674.prol, %B3094.prol ]
  %69 = sub nsw i64 %.566748564858.ph, %arg.y.2
  %70 = icmp ugt i64 %69, -8
  br i1 %70, label %B3120, label %B3094.preheader1045

B3094.preheader1045:                              ; preds = %B3094.prol.loopexit
  br label %B3094

B3208.if:                                         ; preds = %B3208
  %71 = icmp eq ptr %arg.post.0, null
  br i1 %71, label %B3208.if.if, label %B3208.if.endif, !prof !0

B3208.else:                                       ; preds = %B3208
  store i64 0, ptr %.6125, align 8
  %.6139 = call i32 %arg.post.2(ptr nonnull %.6125, ptr nonnull %excinfo.16, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, double %t_new.8.14661, ptr %arg.log.0, ptr %arg.log.1, i64 %arg.log.2, i64 %arg.log.3, ptr %arg.log.4, i64 %arg.log.5.0, i64 %arg.log.5.1, i64 %arg.log.6.0, i64 %arg.log.6.1)
  %.6149 = load i64, ptr %.6125, align 8
  switch i32 %.6139, label %B3208.else.if.if [
    i32 -2, label %B3208.endif
    i32 0, label %B3208.endif
  ], !prof !4

B3208.endif:                                      ; preds = %B3208.else, %B3208.else, %B3208.if.endif
  %.6082.0 = phi i64 [ %.6121, %B3208.if.endif ], [ %.6149, %B3208.else ], [ %.6149, %B3208.else ]
  %.6166 = icmp slt i64 %.6082.0, 0
  br i1 %.6166, label %B3306, label %B3314

B3208.if.if:                                      ; preds = %B3208.if
  call void @numba_gil_ensure(ptr nonnull %.6090)
  %.6093 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.6094 = call ptr @PyObject_GetAttrString(ptr %.6093, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.6093)
  %.6102 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091, i32 560, ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.sha1)
  %.6103 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.6094, ptr %arg.post.1, ptr %.6102, ptr null)
  %.6104 = icmp eq ptr %.6103, null
  br i1 %.6104, label %B3208.if.if.if, label %B3208.if.if.endif, !prof !0

B3208.if.endif:                                   ; preds = %B3208.if, %B3208.if.if.endif
  %fptr_of_post.0 = phi ptr [ %.6111, %B3208.if.if.endif ], [ %arg.post.0, %B3208.if ]
  %.6121 = call i64 %fptr_of_post.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert, double %t_new.8.14661, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.6074.fca.6.1.insert)
  br label %B3208.endif

B3208.if.if.if:                                   ; preds = %B3208.if.if
  store ptr @.const.picklebuf.b1f499986692c125c12fdde1e97e44c2fd7327d1, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B3208.if.if.endif:                                ; preds = %B3208.if.if
  %.6111 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.6103)
  call void @Py_DecRef(ptr nonnull %.6103)
  call void @numba_gil_release(ptr nonnull %.6090)
  br label %B3208.if.endif

B3208.else.if.if:                                 ; preds = %B3208.else
  %.6147 = icmp sgt i32 %.6139, 0
  %.6140 = load ptr, ptr %excinfo.16, align 8
  %.6148 = select i1 %.6147, ptr %.6140, ptr undef
  store ptr %.6148, ptr %excinfo, align 8
  br label %common.ret

B3440.if:                                         ; preds = %B3440
  %72 = icmp eq ptr %arg.to_ambient.0, null
  br i1 %72, label %B3440.if.if, label %B3440.if.endif, !prof !0

B3440.else:                                       ; preds = %B3440
  store double 0.000000e+00, ptr %.6591, align 8
  %.6603 = call i32 %arg.to_ambient.2(ptr nonnull %.6591, ptr nonnull %excinfo.17, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, ptr %arg.Y_out.0, ptr %arg.Y_out.1, i64 %arg.Y_out.5.1, i64 %arg.Y_out.3, ptr %.6506, i64 %arg.Y_out.5.1, i64 %arg.Y_out.6.1)
  switch i32 %.6603, label %B3440.else.if.if [
    i32 -2, label %B3440.endif
    i32 0, label %B3440.endif
  ], !prof !4

B3440.endif:                                      ; preds = %B3440.else, %B3440.else, %B3440.if.endif
  call void @NRT_decref(ptr %arg.Y_out.0)
  %sunkaddr1265 = getelementptr i8, ptr %arg.ist.4, i64 16
  %.6658 = load i64, ptr %sunkaddr1265, align 8
  %.6672 = icmp slt i64 %.6658, 0
  %.6673 = select i1 %.6672, i64 %arg.t_eval.5.0, i64 0
  %73 = getelementptr double, ptr %arg.t_eval.4, i64 %.6658
  %.6687 = getelementptr double, ptr %73, i64 %.6673
  %.6688 = load double, ptr %.6687, align 8
  %sunkaddr1266 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.6718 = load i64, ptr %sunkaddr1266, align 8
  %.6732 = icmp slt i64 %.6718, 0
  %.6733 = select i1 %.6732, i64 %arg.T_out.5.0, i64 0
  %74 = getelementptr double, ptr %arg.T_out.4, i64 %.6718
  %.6747 = getelementptr double, ptr %74, i64 %.6733
  store double %.6688, ptr %.6747, align 8
  %.6778 = load i64, ptr %sunkaddr1266, align 8
  %.6779 = add nsw i64 %.6778, 1
  store i64 %.6779, ptr %sunkaddr1266, align 8
  %.6839 = load i64, ptr %sunkaddr1265, align 8
  %.6840 = add nsw i64 %.6839, 1
  store i64 %.6840, ptr %sunkaddr1265, align 8
  %.6902 = icmp slt i64 %.6840, %arg.t_eval.2
  br i1 %.6902, label %B3686, label %B3870

B3440.if.if:                                      ; preds = %B3440.if
  call void @numba_gil_ensure(ptr nonnull %.6556)
  %.6559 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.6560 = call ptr @PyObject_GetAttrString(ptr %.6559, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.6559)
  %.6568 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1)
  %.6569 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.6560, ptr %arg.to_ambient.1, ptr %.6568, ptr null)
  %.6570 = icmp eq ptr %.6569, null
  br i1 %.6570, label %B3440.if.if.if, label %B3440.if.if.endif, !prof !0

B3440.if.endif:                                   ; preds = %B3440.if, %B3440.if.if.endif
  %fptr_of_to_ambient.1.0 = phi ptr [ %.6577, %B3440.if.if.endif ], [ %arg.to_ambient.0, %B3440.if ]
  %.6587 = call double %fptr_of_to_ambient.1.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6534.fca.6.0.insert)
  br label %B3440.endif

B3440.if.if.if:                                   ; preds = %B3440.if.if
  store ptr @.const.picklebuf.3ca9c262f616dc09ad7b0c2d49d13087359018c0, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B3440.if.if.endif:                                ; preds = %B3440.if.if
  %.6577 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.6569)
  call void @Py_DecRef(ptr nonnull %.6569)
  call void @numba_gil_release(ptr nonnull %.6556)
  br label %B3440.if.endif

B3440.else.if.if:                                 ; preds = %B3440.else
  %.6611 = icmp sgt i32 %.6603, 0
  %.6604 = load ptr, ptr %excinfo.17, align 8
  %.6612 = select i1 %.6611, ptr %.6604, ptr undef
  store ptr %.6612, ptr %excinfo, align 8
  br label %common.ret

B3734.if:                                         ; preds = %B3734
  %75 = icmp eq ptr %arg.to_ambient.0, null
  br i1 %75, label %B3734.if.if, label %B3734.if.endif, !prof !0

B3734.else:                                       ; preds = %B3734
  store double 0.000000e+00, ptr %.7127, align 8
  %.7139 = call i32 %arg.to_ambient.2(ptr nonnull %.7127, ptr nonnull %excinfo.18, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, ptr %arg.Y_out.0, ptr %arg.Y_out.1, i64 %arg.Y_out.5.1, i64 %arg.Y_out.3, ptr %.7042, i64 %arg.Y_out.5.1, i64 %arg.Y_out.6.1)
  switch i32 %.7139, label %B3734.else.if.if [
    i32 -2, label %B3734.endif
    i32 0, label %B3734.endif
  ], !prof !4

B3734.endif:                                      ; preds = %B3734.else, %B3734.else, %B3734.if.endif
  call void @NRT_decref(ptr %arg.Y_out.0)
  %sunkaddr1267 = getelementptr i8, ptr %arg.ist.4, i64 8
  %.7194 = load i64, ptr %sunkaddr1267, align 8
  %.7209 = icmp slt i64 %.7194, 0
  %.7210 = select i1 %.7209, i64 %arg.T_out.5.0, i64 0
  %76 = getelementptr double, ptr %arg.T_out.4, i64 %.7194
  %.7224 = getelementptr double, ptr %76, i64 %.7210
  store double %t_new.8.14661, ptr %.7224, align 8
  %.7255 = load i64, ptr %sunkaddr1267, align 8
  %.7256 = add nsw i64 %.7255, 1
  store i64 %.7256, ptr %sunkaddr1267, align 8
  br label %B3870

B3734.if.if:                                      ; preds = %B3734.if
  call void @numba_gil_ensure(ptr nonnull %.7092)
  %.7095 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.7096 = call ptr @PyObject_GetAttrString(ptr %.7095, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.7095)
  %.7104 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1)
  %.7105 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.7096, ptr %arg.to_ambient.1, ptr %.7104, ptr null)
  %.7106 = icmp eq ptr %.7105, null
  br i1 %.7106, label %B3734.if.if.if, label %B3734.if.if.endif, !prof !0

B3734.if.endif:                                   ; preds = %B3734.if, %B3734.if.if.endif
  %fptr_of_to_ambient.2.0 = phi ptr [ %.7113, %B3734.if.if.endif ], [ %arg.to_ambient.0, %B3734.if ]
  %.7123 = call double %fptr_of_to_ambient.2.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7070.fca.6.0.insert)
  br label %B3734.endif

B3734.if.if.if:                                   ; preds = %B3734.if.if
  store ptr @.const.picklebuf.4bd459b058f64e017c239a70098f62534352b29d, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B3734.if.if.endif:                                ; preds = %B3734.if.if
  %.7113 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.7105)
  call void @Py_DecRef(ptr nonnull %.7105)
  call void @numba_gil_release(ptr nonnull %.7092)
  br label %B3734.if.endif

B3734.else.if.if:                                 ; preds = %B3734.else
  %.7147 = icmp sgt i32 %.7139, 0
  %.7140 = load ptr, ptr %excinfo.18, align 8
  %.7148 = select i1 %.7147, ptr %.7140, ptr undef
  store ptr %.7148, ptr %excinfo, align 8
  br label %common.ret

B3870.if:                                         ; preds = %B3870
  %77 = icmp eq ptr %arg.invariants.0, null
  br i1 %77, label %B3870.if.if, label %B3870.if.endif, !prof !0

B3870.else:                                       ; preds = %B3870
  store double 0.000000e+00, ptr %.7342, align 8
  %.7354 = call i32 %arg.invariants.2(ptr nonnull %.7342, ptr nonnull %excinfo.19, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0, ptr %arg.inv.0, ptr %arg.inv.1, i64 %arg.inv.2, i64 %arg.inv.3, ptr %arg.inv.4, i64 %arg.inv.5.0, i64 %arg.inv.6.0)
  switch i32 %.7354, label %B3870.else.if.if [
    i32 -2, label %B3870.endif
    i32 0, label %B3870.endif
  ], !prof !4

B3870.endif:                                      ; preds = %B3870.else, %B3870.else, %B3870.if.endif
  %sunkaddr1268 = getelementptr i8, ptr %arg.st.4, i64 48
  %.7407 = load double, ptr %sunkaddr1268, align 8
  %.59.i = load double, ptr %arg.inv.4, align 8, !noalias !14
  %sunkaddr1269 = getelementptr i8, ptr %arg.inv.4, i64 8
  %.88.i = load double, ptr %sunkaddr1269, align 8, !noalias !14
  %.133.i = fcmp oeq double %.7407, 0.000000e+00
  br i1 %.133.i, label %B3870.endif.endif.if.if, label %B0.endif.i, !prof !0

B0.endif.i:                                       ; preds = %B3870.endif
  %sunkaddr1270 = getelementptr i8, ptr %arg.inv.4, i64 16
  %.117.i = load double, ptr %sunkaddr1270, align 8, !noalias !14
  %.147.i = fsub double %.59.i, %.59.i
  %.148.i = fcmp ord double %.147.i, 0.000000e+00
  %.151.i = fsub double %.88.i, %.88.i
  %.152.i = fcmp ord double %.151.i, 0.000000e+00
  %or.cond.i = select i1 %.148.i, i1 %.152.i, i1 false
  %.155.i = fsub double %.117.i, %.117.i
  %.156.i = fcmp ord double %.155.i, 0.000000e+00
  %or.cond141.i = select i1 %or.cond.i, i1 %.156.i, i1 false
  br i1 %or.cond141.i, label %B3970, label %B3954

B3870.if.if:                                      ; preds = %B3870.if
  call void @numba_gil_ensure(ptr nonnull %.7307)
  %.7310 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type)
  %.7311 = call ptr @PyObject_GetAttrString(ptr %.7310, ptr nonnull @.const._get_wrapper_address)
  call void @Py_DecRef(ptr %.7310)
  %.7319 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1)
  %.7320 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.7311, ptr %arg.invariants.1, ptr %.7319, ptr null)
  %.7321 = icmp eq ptr %.7320, null
  br i1 %.7321, label %B3870.if.if.if, label %B3870.if.if.endif, !prof !0

B3870.if.endif:                                   ; preds = %B3870.if, %B3870.if.if.endif
  %fptr_of_invariants.0 = phi ptr [ %.7328, %B3870.if.if.endif ], [ %arg.invariants.0, %B3870.if ]
  %.7338 = call double %fptr_of_invariants.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.309.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1265.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.1266.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7291.fca.6.0.insert)
  br label %B3870.endif

B3870.if.if.if:                                   ; preds = %B3870.if.if
  store ptr @.const.picklebuf.d164b050fccb0b900982ad985a7025ea41290c6a, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B3870.if.if.endif:                                ; preds = %B3870.if.if
  %.7328 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.7320)
  call void @Py_DecRef(ptr nonnull %.7320)
  call void @numba_gil_release(ptr nonnull %.7307)
  br label %B3870.if.endif

B3870.else.if.if:                                 ; preds = %B3870.else
  %.7362 = icmp sgt i32 %.7354, 0
  %.7355 = load ptr, ptr %excinfo.19, align 8
  %.7363 = select i1 %.7362, ptr %.7355, ptr undef
  store ptr %.7363, ptr %excinfo, align 8
  br label %common.ret

B3870.endif.endif.if.if:                          ; preds = %B3870.endif
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.55, ptr %excinfo, align 8
  br label %common.ret
}

; Function Attrs: mustprogress nocallback nofree nounwind willreturn memory(argmem: write)
declare void @llvm.memset.p0.i64(ptr writeonly captures(none), i8, i64, i1 immarg) #0

; Function Attrs: nofree nounwind memory(read)
declare double @numba_nextafter(double, double) local_unnamed_addr #1

declare void @numba_gil_ensure(ptr) local_unnamed_addr

declare ptr @PyImport_ImportModule(ptr) local_unnamed_addr

declare ptr @PyObject_GetAttrString(ptr, ptr) local_unnamed_addr

declare void @Py_DecRef(ptr) local_unnamed_addr

declare ptr @numba_unpickle(ptr, i32, ptr) local_unnamed_addr

declare ptr @PyObject_CallFunctionObjArgs(ptr, ...) local_unnamed_addr

declare ptr @PyLong_AsVoidPtr(ptr) local_unnamed_addr

declare void @numba_gil_release(ptr) local_unnamed_addr

define ptr @_ZN7cpython6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE(ptr readnone captures(none) %py_closure, ptr %py_args, ptr readnone captures(none) %py_kws) local_unnamed_addr {
entry:
  %.5 = alloca ptr, align 8
  %.6 = alloca ptr, align 8
  %.7 = alloca ptr, align 8
  %.8 = alloca ptr, align 8
  %.9 = alloca ptr, align 8
  %.10 = alloca ptr, align 8
  %.11 = alloca ptr, align 8
  %.12 = alloca ptr, align 8
  %.13 = alloca ptr, align 8
  %.14 = alloca ptr, align 8
  %.15 = alloca ptr, align 8
  %.16 = alloca ptr, align 8
  %.17 = alloca ptr, align 8
  %.18 = alloca ptr, align 8
  %.19 = alloca ptr, align 8
  %.20 = alloca ptr, align 8
  %.21 = alloca ptr, align 8
  %.22 = alloca ptr, align 8
  %.23 = alloca ptr, align 8
  %.24 = alloca ptr, align 8
  %.25 = alloca ptr, align 8
  %.26 = alloca ptr, align 8
  %.27 = call i32 (ptr, ptr, i64, i64, ...) @PyArg_UnpackTuple(ptr %py_args, ptr nonnull @.const._drive, i64 22, i64 22, ptr nonnull %.5, ptr nonnull %.6, ptr nonnull %.7, ptr nonnull %.8, ptr nonnull %.9, ptr nonnull %.10, ptr nonnull %.11, ptr nonnull %.12, ptr nonnull %.13, ptr nonnull %.14, ptr nonnull %.15, ptr nonnull %.16, ptr nonnull %.17, ptr nonnull %.18, ptr nonnull %.19, ptr nonnull %.20, ptr nonnull %.21, ptr nonnull %.22, ptr nonnull %.23, ptr nonnull %.24, ptr nonnull %.25, ptr nonnull %.26)
  %.28 = icmp eq i32 %.27, 0
  %.270 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  %.293 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.270, i8 0, i64 56, i1 false)
  %.316 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.293, i8 0, i64 56, i1 false)
  %.339 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.316, i8 0, i64 56, i1 false)
  %.362 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.339, i8 0, i64 56, i1 false)
  %.385 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.362, i8 0, i64 56, i1 false)
  %.408 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.385, i8 0, i64 56, i1 false)
  %.431 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.408, i8 0, i64 56, i1 false)
  %.456 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.431, i8 0, i64 72, i1 false)
  %.481 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.456, i8 0, i64 72, i1 false)
  %.504 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.481, i8 0, i64 56, i1 false)
  %.529 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.504, i8 0, i64 72, i1 false)
  %.554 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.529, i8 0, i64 72, i1 false)
  %.577 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.554, i8 0, i64 56, i1 false)
  %.600 = alloca { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.577, i8 0, i64 56, i1 false)
  %.623 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.600, i8 0, i64 56, i1 false)
  %.648 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.623, i8 0, i64 72, i1 false)
  %.672 = alloca i64, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.648, i8 0, i64 72, i1 false)
  store i64 0, ptr %.672, align 8
  %excinfo = alloca ptr, align 8
  store ptr null, ptr %excinfo, align 8
  br i1 %.28, label %common.ret, label %entry.endif, !prof !0

common.ret:                                       ; preds = %entry.endif.endif.endif.e...endif.2.endif.thread, %entry.endif.endif.endif.e...endif.12, %entry.endif.endif.endif.e...endif.12.if, %entry.endif.endif.endif.e...endif.12.endif.endif, %entry.endif.endif.endif.e...if.12.endif.if, %entry.endif.endif.endif.e...if.12.endif, %entry.endif.endif.endif.e...endif.1.endif.endif, %entry.endif.endif.endif.e...endif.1.endif, %entry.endif.endif.endif.e...endif.endif.endif.endif, %entry.endif.endif.endif.e...endif.endif.endif, %entry.endif.endif.endif.e...endif, %entry.endif.endif.endif.endif.endif.endif.endif.endif, %entry.endif.endif.endif.endif.endif.endif, %entry.endif.endif.endif.endif.endif, %entry.endif.endif.endif, %entry.endif.endif, %arg5.err, %entry, %entry.endif.endif.endif.e...if.12.if.if, %entry.endif.endif.endif.e...endif.11, %entry.endif.if
  %common.ret.op = phi ptr [ null, %entry.endif.endif.endif.e...if.12.if.if ], [ null, %entry ], [ null, %entry.endif.if ], [ null, %arg5.err ], [ null, %entry.endif.endif ], [ null, %entry.endif.endif.endif ], [ null, %entry.endif.endif.endif.endif.endif ], [ null, %entry.endif.endif.endif.endif.endif.endif ], [ null, %entry.endif.endif.endif.endif.endif.endif.endif.endif ], [ null, %entry.endif.endif.endif.e...endif ], [ null, %entry.endif.endif.endif.e...endif.endif.endif ], [ null, %entry.endif.endif.endif.e...endif.endif.endif.endif ], [ null, %entry.endif.endif.endif.e...endif.1.endif ], [ null, %entry.endif.endif.endif.e...endif.12.if ], [ %.802, %entry.endif.endif.endif.e...endif.11 ], [ null, %entry.endif.endif.endif.e...endif.1.endif.endif ], [ null, %entry.endif.endif.endif.e...endif.2.endif.thread ], [ null, %entry.endif.endif.endif.e...endif.12 ], [ null, %entry.endif.endif.endif.e...if.12.endif ], [ null, %entry.endif.endif.endif.e...if.12.endif.if ], [ null, %entry.endif.endif.endif.e...endif.12.endif.endif ]
  ret ptr %common.ret.op

entry.endif:                                      ; preds = %entry
  %.32 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE, align 8
  %.35 = icmp eq ptr %.32, null
  br i1 %.35, label %entry.endif.if, label %entry.endif.endif, !prof !0

entry.endif.if:                                   ; preds = %entry.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_RuntimeError, ptr nonnull @".const.missing Environment: _ZN08NumbaEnv6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE")
  br label %common.ret

entry.endif.endif:                                ; preds = %entry.endif
  %.39 = load ptr, ptr %.5, align 8
  %.43 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.44 = call ptr @PyObject_GetAttrString(ptr %.43, ptr nonnull @.const._get_wrapper_address.2)
  call void @Py_DecRef(ptr %.43)
  %.52 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.3, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.4)
  %.53 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.44, ptr %.39, ptr %.52, ptr null)
  %.54 = icmp eq ptr %.53, null
  br i1 %.54, label %common.ret, label %entry.endif.endif.endif, !prof !0

entry.endif.endif.endif:                          ; preds = %entry.endif.endif
  %.57 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.53)
  call void @Py_DecRef(ptr nonnull %.53)
  %.63 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.64 = call ptr @PyObject_GetAttrString(ptr %.63, ptr nonnull @.const._get_jit_address)
  call void @Py_DecRef(ptr %.63)
  %.72 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.3, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.4)
  %.73 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.64, ptr %.39, ptr %.72, ptr null)
  %.74 = icmp eq ptr %.73, null
  br i1 %.74, label %common.ret, label %entry.endif.endif.endif.endif.endif, !prof !0

entry.endif.endif.endif.endif.endif:              ; preds = %entry.endif.endif.endif
  %.77 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.73)
  call void @Py_DecRef(ptr nonnull %.73)
  %.85 = load ptr, ptr %.6, align 8
  %.89 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.90 = call ptr @PyObject_GetAttrString(ptr %.89, ptr nonnull @.const._get_wrapper_address.2)
  call void @Py_DecRef(ptr %.89)
  %.98 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.5, i32 495, ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.sha1.6)
  %.99 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.90, ptr %.85, ptr %.98, ptr null)
  %.100 = icmp eq ptr %.99, null
  br i1 %.100, label %common.ret, label %entry.endif.endif.endif.endif.endif.endif, !prof !0

entry.endif.endif.endif.endif.endif.endif:        ; preds = %entry.endif.endif.endif.endif.endif
  %.103 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.99)
  call void @Py_DecRef(ptr nonnull %.99)
  %.109 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.110 = call ptr @PyObject_GetAttrString(ptr %.109, ptr nonnull @.const._get_jit_address)
  call void @Py_DecRef(ptr %.109)
  %.118 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.5, i32 495, ptr nonnull @.const.pickledata.40911f92b658a87902930291e94b9fb51b28a41a.sha1.6)
  %.119 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.110, ptr %.85, ptr %.118, ptr null)
  %.120 = icmp eq ptr %.119, null
  br i1 %.120, label %common.ret, label %entry.endif.endif.endif.endif.endif.endif.endif.endif, !prof !0

entry.endif.endif.endif.endif.endif.endif.endif.endif: ; preds = %entry.endif.endif.endif.endif.endif.endif
  %.123 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.119)
  call void @Py_DecRef(ptr nonnull %.119)
  %.131 = load ptr, ptr %.7, align 8
  %.135 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.136 = call ptr @PyObject_GetAttrString(ptr %.135, ptr nonnull @.const._get_wrapper_address.2)
  call void @Py_DecRef(ptr %.135)
  %.144 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.7, i32 560, ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.sha1.8)
  %.145 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.136, ptr %.131, ptr %.144, ptr null)
  %.146 = icmp eq ptr %.145, null
  br i1 %.146, label %common.ret, label %entry.endif.endif.endif.e...endif, !prof !0

entry.endif.endif.endif.e...endif:                ; preds = %entry.endif.endif.endif.endif.endif.endif.endif.endif
  %.149 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.145)
  call void @Py_DecRef(ptr nonnull %.145)
  %.155 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.156 = call ptr @PyObject_GetAttrString(ptr %.155, ptr nonnull @.const._get_jit_address)
  call void @Py_DecRef(ptr %.155)
  %.164 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.7, i32 560, ptr nonnull @.const.pickledata.1c82c2413ef0a1afb9729e709f895f5e8de5d091.sha1.8)
  %.165 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.156, ptr %.131, ptr %.164, ptr null)
  %.166 = icmp eq ptr %.165, null
  br i1 %.166, label %common.ret, label %entry.endif.endif.endif.e...endif.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.endif.endif:    ; preds = %entry.endif.endif.endif.e...endif
  %.169 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.165)
  call void @Py_DecRef(ptr nonnull %.165)
  %.177 = load ptr, ptr %.8, align 8
  %.181 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.182 = call ptr @PyObject_GetAttrString(ptr %.181, ptr nonnull @.const._get_wrapper_address.2)
  call void @Py_DecRef(ptr %.181)
  %.190 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.9, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1.10)
  %.191 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.182, ptr %.177, ptr %.190, ptr null)
  %.192 = icmp eq ptr %.191, null
  br i1 %.192, label %common.ret, label %entry.endif.endif.endif.e...endif.endif.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.endif.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.endif.endif
  %.195 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.191)
  call void @Py_DecRef(ptr nonnull %.191)
  %.201 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.202 = call ptr @PyObject_GetAttrString(ptr %.201, ptr nonnull @.const._get_jit_address)
  call void @Py_DecRef(ptr %.201)
  %.210 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.9, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1.10)
  %.211 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.202, ptr %.177, ptr %.210, ptr null)
  %.212 = icmp eq ptr %.211, null
  br i1 %.212, label %common.ret, label %entry.endif.endif.endif.e...endif.1.endif, !prof !0

entry.endif.endif.endif.e...endif.1.endif:        ; preds = %entry.endif.endif.endif.e...endif.endif.endif.endif
  %.215 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.211)
  call void @Py_DecRef(ptr nonnull %.211)
  %.223 = load ptr, ptr %.9, align 8
  %.227 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.228 = call ptr @PyObject_GetAttrString(ptr %.227, ptr nonnull @.const._get_wrapper_address.2)
  call void @Py_DecRef(ptr %.227)
  %.236 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.9, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1.10)
  %.237 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.228, ptr %.223, ptr %.236, ptr null)
  %.238 = icmp eq ptr %.237, null
  br i1 %.238, label %common.ret, label %entry.endif.endif.endif.e...endif.1.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.1.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.1.endif
  %.241 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.237)
  call void @Py_DecRef(ptr nonnull %.237)
  %.247 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.1)
  %.248 = call ptr @PyObject_GetAttrString(ptr %.247, ptr nonnull @.const._get_jit_address)
  call void @Py_DecRef(ptr %.247)
  %.256 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.9, i32 498, ptr nonnull @.const.pickledata.6ba8e0c0fe8340e844973c045eedc9a19114e908.sha1.10)
  %.257 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.248, ptr %.223, ptr %.256, ptr null)
  %.258 = icmp eq ptr %.257, null
  br i1 %.258, label %common.ret, label %entry.endif.endif.endif.e...endif.2, !prof !0

entry.endif.endif.endif.e...endif.2:              ; preds = %entry.endif.endif.endif.e...endif.1.endif.endif
  %.261 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.257)
  call void @Py_DecRef(ptr nonnull %.257)
  %.269 = load ptr, ptr %.10, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.270, i8 0, i64 56, i1 false)
  %.274 = call i32 @NRT_adapt_ndarray_from_python(ptr %.269, ptr nonnull %.270)
  %sunkaddr = getelementptr inbounds i8, ptr %.270, i64 24
  %.278 = load i64, ptr %sunkaddr, align 8
  %.279 = icmp ne i64 %.278, 8
  %.280 = icmp ne i32 %.274, 0
  %.281 = or i1 %.280, %.279
  br i1 %.281, label %entry.endif.endif.endif.e...endif.2.endif.thread, label %entry.endif.endif.endif.e...endif.2.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.2.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.2
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %common.ret

entry.endif.endif.endif.e...endif.2.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.2
  %.285.fca.0.load = load ptr, ptr %.270, align 8
  %sunkaddr1 = getelementptr inbounds i8, ptr %.270, i64 8
  %.285.fca.1.load = load ptr, ptr %sunkaddr1, align 8
  %sunkaddr2 = getelementptr inbounds i8, ptr %.270, i64 16
  %.285.fca.2.load = load i64, ptr %sunkaddr2, align 8
  %sunkaddr3 = getelementptr inbounds i8, ptr %.270, i64 32
  %.285.fca.4.load = load ptr, ptr %sunkaddr3, align 8
  %sunkaddr4 = getelementptr inbounds i8, ptr %.270, i64 40
  %.285.fca.5.0.load = load i64, ptr %sunkaddr4, align 8
  %sunkaddr5 = getelementptr inbounds i8, ptr %.270, i64 48
  %.285.fca.6.0.load = load i64, ptr %sunkaddr5, align 8
  %.292 = load ptr, ptr %.11, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.293, i8 0, i64 56, i1 false)
  %.297 = call i32 @NRT_adapt_ndarray_from_python(ptr %.292, ptr nonnull %.293)
  %sunkaddr6 = getelementptr inbounds i8, ptr %.293, i64 24
  %.301 = load i64, ptr %sunkaddr6, align 8
  %.302 = icmp ne i64 %.301, 8
  %.303 = icmp ne i32 %.297, 0
  %.304 = or i1 %.303, %.302
  br i1 %.304, label %entry.endif.endif.endif.e...endif.2.endif.endif.endif.thread, label %entry.endif.endif.endif.e...endif.3, !prof !0

arg5.err:                                         ; preds = %entry.endif.endif.endif.e...endif.2.endif.endif.endif.thread, %arg6.err
  call void @NRT_decref(ptr %.285.fca.0.load)
  br label %common.ret

entry.endif.endif.endif.e...endif.2.endif.endif.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.2.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg5.err

entry.endif.endif.endif.e...endif.3:              ; preds = %entry.endif.endif.endif.e...endif.2.endif.endif
  %.308.fca.0.load = load ptr, ptr %.293, align 8
  %sunkaddr7 = getelementptr inbounds i8, ptr %.293, i64 8
  %.308.fca.1.load = load ptr, ptr %sunkaddr7, align 8
  %sunkaddr8 = getelementptr inbounds i8, ptr %.293, i64 16
  %.308.fca.2.load = load i64, ptr %sunkaddr8, align 8
  %sunkaddr9 = getelementptr inbounds i8, ptr %.293, i64 32
  %.308.fca.4.load = load ptr, ptr %sunkaddr9, align 8
  %sunkaddr10 = getelementptr inbounds i8, ptr %.293, i64 40
  %.308.fca.5.0.load = load i64, ptr %sunkaddr10, align 8
  %sunkaddr11 = getelementptr inbounds i8, ptr %.293, i64 48
  %.308.fca.6.0.load = load i64, ptr %sunkaddr11, align 8
  %.315 = load ptr, ptr %.12, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.316, i8 0, i64 56, i1 false)
  %.320 = call i32 @NRT_adapt_ndarray_from_python(ptr %.315, ptr nonnull %.316)
  %sunkaddr12 = getelementptr inbounds i8, ptr %.316, i64 24
  %.324 = load i64, ptr %sunkaddr12, align 8
  %.325 = icmp ne i64 %.324, 8
  %.326 = icmp ne i32 %.320, 0
  %.327 = or i1 %.326, %.325
  br i1 %.327, label %entry.endif.endif.endif.e...endif.3.endif.thread, label %entry.endif.endif.endif.e...endif.3.endif.endif, !prof !0

arg6.err:                                         ; preds = %entry.endif.endif.endif.e...endif.3.endif.thread, %arg7.err
  call void @NRT_decref(ptr %.308.fca.0.load)
  br label %arg5.err

entry.endif.endif.endif.e...endif.3.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.3
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg6.err

entry.endif.endif.endif.e...endif.3.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.3
  %.331.fca.0.load = load ptr, ptr %.316, align 8
  %sunkaddr13 = getelementptr inbounds i8, ptr %.316, i64 8
  %.331.fca.1.load = load ptr, ptr %sunkaddr13, align 8
  %sunkaddr14 = getelementptr inbounds i8, ptr %.316, i64 16
  %.331.fca.2.load = load i64, ptr %sunkaddr14, align 8
  %sunkaddr15 = getelementptr inbounds i8, ptr %.316, i64 32
  %.331.fca.4.load = load ptr, ptr %sunkaddr15, align 8
  %sunkaddr16 = getelementptr inbounds i8, ptr %.316, i64 40
  %.331.fca.5.0.load = load i64, ptr %sunkaddr16, align 8
  %sunkaddr17 = getelementptr inbounds i8, ptr %.316, i64 48
  %.331.fca.6.0.load = load i64, ptr %sunkaddr17, align 8
  %.338 = load ptr, ptr %.13, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.339, i8 0, i64 56, i1 false)
  %.343 = call i32 @NRT_adapt_ndarray_from_python(ptr %.338, ptr nonnull %.339)
  %sunkaddr18 = getelementptr inbounds i8, ptr %.339, i64 24
  %.347 = load i64, ptr %sunkaddr18, align 8
  %.348 = icmp ne i64 %.347, 8
  %.349 = icmp ne i32 %.343, 0
  %.350 = or i1 %.349, %.348
  br i1 %.350, label %entry.endif.endif.endif.e...endif.3.endif.endif.endif.thread, label %entry.endif.endif.endif.e...endif.4, !prof !0

arg7.err:                                         ; preds = %entry.endif.endif.endif.e...endif.3.endif.endif.endif.thread, %arg8.err
  call void @NRT_decref(ptr %.331.fca.0.load)
  br label %arg6.err

entry.endif.endif.endif.e...endif.3.endif.endif.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.3.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg7.err

entry.endif.endif.endif.e...endif.4:              ; preds = %entry.endif.endif.endif.e...endif.3.endif.endif
  %.354.fca.0.load = load ptr, ptr %.339, align 8
  %sunkaddr19 = getelementptr inbounds i8, ptr %.339, i64 32
  %.354.fca.4.load = load ptr, ptr %sunkaddr19, align 8
  %.361 = load ptr, ptr %.14, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.362, i8 0, i64 56, i1 false)
  %.366 = call i32 @NRT_adapt_ndarray_from_python(ptr %.361, ptr nonnull %.362)
  %sunkaddr20 = getelementptr inbounds i8, ptr %.362, i64 24
  %.370 = load i64, ptr %sunkaddr20, align 8
  %.371 = icmp ne i64 %.370, 8
  %.372 = icmp ne i32 %.366, 0
  %.373 = or i1 %.372, %.371
  br i1 %.373, label %entry.endif.endif.endif.e...endif.4.endif.thread, label %entry.endif.endif.endif.e...endif.4.endif.endif, !prof !0

arg8.err:                                         ; preds = %entry.endif.endif.endif.e...endif.4.endif.thread, %arg9.err
  call void @NRT_decref(ptr %.354.fca.0.load)
  br label %arg7.err

entry.endif.endif.endif.e...endif.4.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.4
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg8.err

entry.endif.endif.endif.e...endif.4.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.4
  %.377.fca.0.load = load ptr, ptr %.362, align 8
  %sunkaddr21 = getelementptr inbounds i8, ptr %.362, i64 32
  %.377.fca.4.load = load ptr, ptr %sunkaddr21, align 8
  %.384 = load ptr, ptr %.15, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.385, i8 0, i64 56, i1 false)
  %.389 = call i32 @NRT_adapt_ndarray_from_python(ptr %.384, ptr nonnull %.385)
  %sunkaddr22 = getelementptr inbounds i8, ptr %.385, i64 24
  %.393 = load i64, ptr %sunkaddr22, align 8
  %.394 = icmp ne i64 %.393, 8
  %.395 = icmp ne i32 %.389, 0
  %.396 = or i1 %.395, %.394
  br i1 %.396, label %entry.endif.endif.endif.e...endif.4.endif.endif.endif.thread, label %entry.endif.endif.endif.e...endif.5, !prof !0

arg9.err:                                         ; preds = %entry.endif.endif.endif.e...endif.4.endif.endif.endif.thread, %arg10.err
  call void @NRT_decref(ptr %.377.fca.0.load)
  br label %arg8.err

entry.endif.endif.endif.e...endif.4.endif.endif.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.4.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg9.err

entry.endif.endif.endif.e...endif.5:              ; preds = %entry.endif.endif.endif.e...endif.4.endif.endif
  %.400.fca.0.load = load ptr, ptr %.385, align 8
  %sunkaddr23 = getelementptr inbounds i8, ptr %.385, i64 16
  %.400.fca.2.load = load i64, ptr %sunkaddr23, align 8
  %sunkaddr24 = getelementptr inbounds i8, ptr %.385, i64 32
  %.400.fca.4.load = load ptr, ptr %sunkaddr24, align 8
  %sunkaddr25 = getelementptr inbounds i8, ptr %.385, i64 40
  %.400.fca.5.0.load = load i64, ptr %sunkaddr25, align 8
  %.407 = load ptr, ptr %.16, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.408, i8 0, i64 56, i1 false)
  %.412 = call i32 @NRT_adapt_ndarray_from_python(ptr %.407, ptr nonnull %.408)
  %sunkaddr26 = getelementptr inbounds i8, ptr %.408, i64 24
  %.416 = load i64, ptr %sunkaddr26, align 8
  %.417 = icmp ne i64 %.416, 8
  %.418 = icmp ne i32 %.412, 0
  %.419 = or i1 %.418, %.417
  br i1 %.419, label %entry.endif.endif.endif.e...endif.5.endif.thread, label %entry.endif.endif.endif.e...endif.5.endif.endif, !prof !0

arg10.err:                                        ; preds = %entry.endif.endif.endif.e...endif.5.endif.thread, %arg11.err
  call void @NRT_decref(ptr %.400.fca.0.load)
  br label %arg9.err

entry.endif.endif.endif.e...endif.5.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.5
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg10.err

entry.endif.endif.endif.e...endif.5.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.5
  %.423.fca.0.load = load ptr, ptr %.408, align 8
  %sunkaddr27 = getelementptr inbounds i8, ptr %.408, i64 32
  %.423.fca.4.load = load ptr, ptr %sunkaddr27, align 8
  %sunkaddr28 = getelementptr inbounds i8, ptr %.408, i64 40
  %.423.fca.5.0.load = load i64, ptr %sunkaddr28, align 8
  %.430 = load ptr, ptr %.17, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.431, i8 0, i64 72, i1 false)
  %.435 = call i32 @NRT_adapt_ndarray_from_python(ptr %.430, ptr nonnull %.431)
  %sunkaddr29 = getelementptr inbounds i8, ptr %.431, i64 24
  %.439 = load i64, ptr %sunkaddr29, align 8
  %.440 = icmp ne i64 %.439, 8
  %.441 = icmp ne i32 %.435, 0
  %.442 = or i1 %.441, %.440
  br i1 %.442, label %entry.endif.endif.endif.e...endif.5.endif.endif.if, label %entry.endif.endif.endif.e...endif.5.endif.endif.endif, !prof !0

arg11.err:                                        ; preds = %entry.endif.endif.endif.e...endif.5.endif.endif.endif, %arg12.err
  call void @NRT_decref(ptr %.423.fca.0.load)
  br label %arg10.err

entry.endif.endif.endif.e...endif.5.endif.endif.if: ; preds = %entry.endif.endif.endif.e...endif.5.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %entry.endif.endif.endif.e...endif.5.endif.endif.endif

entry.endif.endif.endif.e...endif.5.endif.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.5.endif.endif.if, %entry.endif.endif.endif.e...endif.5.endif.endif
  %.446.fca.0.load = load ptr, ptr %.431, align 8
  %sunkaddr30 = getelementptr inbounds i8, ptr %.431, i64 8
  %.446.fca.1.load = load ptr, ptr %sunkaddr30, align 8
  %sunkaddr31 = getelementptr inbounds i8, ptr %.431, i64 32
  %.446.fca.4.load = load ptr, ptr %sunkaddr31, align 8
  %sunkaddr32 = getelementptr inbounds i8, ptr %.431, i64 40
  %.446.fca.5.0.load = load i64, ptr %sunkaddr32, align 8
  %sunkaddr33 = getelementptr inbounds i8, ptr %.431, i64 48
  %.446.fca.5.1.load = load i64, ptr %sunkaddr33, align 8
  %sunkaddr34 = getelementptr inbounds i8, ptr %.431, i64 64
  %.446.fca.6.1.load = load i64, ptr %sunkaddr34, align 8
  br i1 %.442, label %arg11.err, label %entry.endif.endif.endif.e...endif.6, !prof !0

entry.endif.endif.endif.e...endif.6:              ; preds = %entry.endif.endif.endif.e...endif.5.endif.endif.endif
  %.455 = load ptr, ptr %.18, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.456, i8 0, i64 72, i1 false)
  %.460 = call i32 @NRT_adapt_ndarray_from_python(ptr %.455, ptr nonnull %.456)
  %sunkaddr35 = getelementptr inbounds i8, ptr %.456, i64 24
  %.464 = load i64, ptr %sunkaddr35, align 8
  %.465 = icmp ne i64 %.464, 8
  %.466 = icmp ne i32 %.460, 0
  %.467 = or i1 %.466, %.465
  br i1 %.467, label %entry.endif.endif.endif.e...endif.6.if, label %entry.endif.endif.endif.e...endif.6.endif, !prof !0

arg12.err:                                        ; preds = %entry.endif.endif.endif.e...endif.6.endif, %arg13.err
  call void @NRT_decref(ptr %.446.fca.0.load)
  br label %arg11.err

entry.endif.endif.endif.e...endif.6.if:           ; preds = %entry.endif.endif.endif.e...endif.6
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %entry.endif.endif.endif.e...endif.6.endif

entry.endif.endif.endif.e...endif.6.endif:        ; preds = %entry.endif.endif.endif.e...endif.6.if, %entry.endif.endif.endif.e...endif.6
  %.471.fca.0.load = load ptr, ptr %.456, align 8
  %sunkaddr36 = getelementptr inbounds i8, ptr %.456, i64 8
  %.471.fca.1.load = load ptr, ptr %sunkaddr36, align 8
  %sunkaddr37 = getelementptr inbounds i8, ptr %.456, i64 16
  %.471.fca.2.load = load i64, ptr %sunkaddr37, align 8
  %sunkaddr38 = getelementptr inbounds i8, ptr %.456, i64 32
  %.471.fca.4.load = load ptr, ptr %sunkaddr38, align 8
  %sunkaddr39 = getelementptr inbounds i8, ptr %.456, i64 40
  %.471.fca.5.0.load = load i64, ptr %sunkaddr39, align 8
  %sunkaddr40 = getelementptr inbounds i8, ptr %.456, i64 48
  %.471.fca.5.1.load = load i64, ptr %sunkaddr40, align 8
  %sunkaddr41 = getelementptr inbounds i8, ptr %.456, i64 56
  %.471.fca.6.0.load = load i64, ptr %sunkaddr41, align 8
  %sunkaddr42 = getelementptr inbounds i8, ptr %.456, i64 64
  %.471.fca.6.1.load = load i64, ptr %sunkaddr42, align 8
  br i1 %.467, label %arg12.err, label %entry.endif.endif.endif.e...endif.6.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.6.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.6.endif
  %.480 = load ptr, ptr %.19, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.481, i8 0, i64 56, i1 false)
  %.485 = call i32 @NRT_adapt_ndarray_from_python(ptr %.480, ptr nonnull %.481)
  %sunkaddr43 = getelementptr inbounds i8, ptr %.481, i64 24
  %.489 = load i64, ptr %sunkaddr43, align 8
  %.490 = icmp ne i64 %.489, 8
  %.491 = icmp ne i32 %.485, 0
  %.492 = or i1 %.491, %.490
  br i1 %.492, label %entry.endif.endif.endif.e...endif.6.endif.endif.endif.thread, label %entry.endif.endif.endif.e...endif.7, !prof !0

arg13.err:                                        ; preds = %entry.endif.endif.endif.e...endif.6.endif.endif.endif.thread, %arg14.err
  call void @NRT_decref(ptr %.471.fca.0.load)
  br label %arg12.err

entry.endif.endif.endif.e...endif.6.endif.endif.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.6.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg13.err

entry.endif.endif.endif.e...endif.7:              ; preds = %entry.endif.endif.endif.e...endif.6.endif.endif
  %.496.fca.0.load = load ptr, ptr %.481, align 8
  %sunkaddr44 = getelementptr inbounds i8, ptr %.481, i64 32
  %.496.fca.4.load = load ptr, ptr %sunkaddr44, align 8
  %.503 = load ptr, ptr %.20, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.504, i8 0, i64 72, i1 false)
  %.508 = call i32 @NRT_adapt_ndarray_from_python(ptr %.503, ptr nonnull %.504)
  %sunkaddr45 = getelementptr inbounds i8, ptr %.504, i64 24
  %.512 = load i64, ptr %sunkaddr45, align 8
  %.513 = icmp ne i64 %.512, 8
  %.514 = icmp ne i32 %.508, 0
  %.515 = or i1 %.514, %.513
  br i1 %.515, label %entry.endif.endif.endif.e...endif.7.if, label %entry.endif.endif.endif.e...endif.7.endif, !prof !0

arg14.err:                                        ; preds = %entry.endif.endif.endif.e...endif.7.endif, %arg15.err
  call void @NRT_decref(ptr %.496.fca.0.load)
  br label %arg13.err

entry.endif.endif.endif.e...endif.7.if:           ; preds = %entry.endif.endif.endif.e...endif.7
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %entry.endif.endif.endif.e...endif.7.endif

entry.endif.endif.endif.e...endif.7.endif:        ; preds = %entry.endif.endif.endif.e...endif.7.if, %entry.endif.endif.endif.e...endif.7
  %.519.fca.0.load = load ptr, ptr %.504, align 8
  %sunkaddr46 = getelementptr inbounds i8, ptr %.504, i64 8
  %.519.fca.1.load = load ptr, ptr %sunkaddr46, align 8
  %sunkaddr47 = getelementptr inbounds i8, ptr %.504, i64 16
  %.519.fca.2.load = load i64, ptr %sunkaddr47, align 8
  %sunkaddr48 = getelementptr inbounds i8, ptr %.504, i64 32
  %.519.fca.4.load = load ptr, ptr %sunkaddr48, align 8
  %sunkaddr49 = getelementptr inbounds i8, ptr %.504, i64 40
  %.519.fca.5.0.load = load i64, ptr %sunkaddr49, align 8
  %sunkaddr50 = getelementptr inbounds i8, ptr %.504, i64 48
  %.519.fca.5.1.load = load i64, ptr %sunkaddr50, align 8
  %sunkaddr51 = getelementptr inbounds i8, ptr %.504, i64 56
  %.519.fca.6.0.load = load i64, ptr %sunkaddr51, align 8
  %sunkaddr52 = getelementptr inbounds i8, ptr %.504, i64 64
  %.519.fca.6.1.load = load i64, ptr %sunkaddr52, align 8
  br i1 %.515, label %arg14.err, label %entry.endif.endif.endif.e...endif.7.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.7.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.7.endif
  %.528 = load ptr, ptr %.21, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.529, i8 0, i64 72, i1 false)
  %.533 = call i32 @NRT_adapt_ndarray_from_python(ptr %.528, ptr nonnull %.529)
  %sunkaddr53 = getelementptr inbounds i8, ptr %.529, i64 24
  %.537 = load i64, ptr %sunkaddr53, align 8
  %.538 = icmp ne i64 %.537, 8
  %.539 = icmp ne i32 %.533, 0
  %.540 = or i1 %.539, %.538
  br i1 %.540, label %entry.endif.endif.endif.e...endif.7.endif.endif.if, label %entry.endif.endif.endif.e...endif.7.endif.endif.endif, !prof !0

arg15.err:                                        ; preds = %entry.endif.endif.endif.e...endif.7.endif.endif.endif, %arg16.err
  call void @NRT_decref(ptr %.519.fca.0.load)
  br label %arg14.err

entry.endif.endif.endif.e...endif.7.endif.endif.if: ; preds = %entry.endif.endif.endif.e...endif.7.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %entry.endif.endif.endif.e...endif.7.endif.endif.endif

entry.endif.endif.endif.e...endif.7.endif.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.7.endif.endif.if, %entry.endif.endif.endif.e...endif.7.endif.endif
  %.544.fca.0.load = load ptr, ptr %.529, align 8
  %sunkaddr54 = getelementptr inbounds i8, ptr %.529, i64 8
  %.544.fca.1.load = load ptr, ptr %sunkaddr54, align 8
  %sunkaddr55 = getelementptr inbounds i8, ptr %.529, i64 16
  %.544.fca.2.load = load i64, ptr %sunkaddr55, align 8
  %sunkaddr56 = getelementptr inbounds i8, ptr %.529, i64 32
  %.544.fca.4.load = load ptr, ptr %sunkaddr56, align 8
  %sunkaddr57 = getelementptr inbounds i8, ptr %.529, i64 40
  %.544.fca.5.0.load = load i64, ptr %sunkaddr57, align 8
  %sunkaddr58 = getelementptr inbounds i8, ptr %.529, i64 48
  %.544.fca.5.1.load = load i64, ptr %sunkaddr58, align 8
  %sunkaddr59 = getelementptr inbounds i8, ptr %.529, i64 56
  %.544.fca.6.0.load = load i64, ptr %sunkaddr59, align 8
  %sunkaddr60 = getelementptr inbounds i8, ptr %.529, i64 64
  %.544.fca.6.1.load = load i64, ptr %sunkaddr60, align 8
  br i1 %.540, label %arg15.err, label %entry.endif.endif.endif.e...endif.8, !prof !0

entry.endif.endif.endif.e...endif.8:              ; preds = %entry.endif.endif.endif.e...endif.7.endif.endif.endif
  %.553 = load ptr, ptr %.22, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.554, i8 0, i64 56, i1 false)
  %.558 = call i32 @NRT_adapt_ndarray_from_python(ptr %.553, ptr nonnull %.554)
  %sunkaddr61 = getelementptr inbounds i8, ptr %.554, i64 24
  %.562 = load i64, ptr %sunkaddr61, align 8
  %.563 = icmp ne i64 %.562, 8
  %.564 = icmp ne i32 %.558, 0
  %.565 = or i1 %.564, %.563
  br i1 %.565, label %entry.endif.endif.endif.e...endif.8.endif.thread, label %entry.endif.endif.endif.e...endif.8.endif.endif, !prof !0

arg16.err:                                        ; preds = %entry.endif.endif.endif.e...endif.8.endif.thread, %arg17.err
  call void @NRT_decref(ptr %.544.fca.0.load)
  br label %arg15.err

entry.endif.endif.endif.e...endif.8.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.8
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg16.err

entry.endif.endif.endif.e...endif.8.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.8
  %.569.fca.0.load = load ptr, ptr %.554, align 8
  %sunkaddr62 = getelementptr inbounds i8, ptr %.554, i64 8
  %.569.fca.1.load = load ptr, ptr %sunkaddr62, align 8
  %sunkaddr63 = getelementptr inbounds i8, ptr %.554, i64 16
  %.569.fca.2.load = load i64, ptr %sunkaddr63, align 8
  %sunkaddr64 = getelementptr inbounds i8, ptr %.554, i64 32
  %.569.fca.4.load = load ptr, ptr %sunkaddr64, align 8
  %sunkaddr65 = getelementptr inbounds i8, ptr %.554, i64 40
  %.569.fca.5.0.load = load i64, ptr %sunkaddr65, align 8
  %sunkaddr66 = getelementptr inbounds i8, ptr %.554, i64 48
  %.569.fca.6.0.load = load i64, ptr %sunkaddr66, align 8
  %.576 = load ptr, ptr %.23, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.577, i8 0, i64 56, i1 false)
  %.581 = call i32 @NRT_adapt_ndarray_from_python(ptr %.576, ptr nonnull %.577)
  %sunkaddr67 = getelementptr inbounds i8, ptr %.577, i64 24
  %.585 = load i64, ptr %sunkaddr67, align 8
  %.586 = icmp ne i64 %.585, 8
  %.587 = icmp ne i32 %.581, 0
  %.588 = or i1 %.587, %.586
  br i1 %.588, label %entry.endif.endif.endif.e...endif.8.endif.endif.endif.thread, label %entry.endif.endif.endif.e...endif.9, !prof !0

arg17.err:                                        ; preds = %entry.endif.endif.endif.e...endif.8.endif.endif.endif.thread, %arg18.err
  call void @NRT_decref(ptr %.569.fca.0.load)
  br label %arg16.err

entry.endif.endif.endif.e...endif.8.endif.endif.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.8.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg17.err

entry.endif.endif.endif.e...endif.9:              ; preds = %entry.endif.endif.endif.e...endif.8.endif.endif
  %.592.fca.0.load = load ptr, ptr %.577, align 8
  %sunkaddr68 = getelementptr inbounds i8, ptr %.577, i64 8
  %.592.fca.1.load = load ptr, ptr %sunkaddr68, align 8
  %sunkaddr69 = getelementptr inbounds i8, ptr %.577, i64 16
  %.592.fca.2.load = load i64, ptr %sunkaddr69, align 8
  %sunkaddr70 = getelementptr inbounds i8, ptr %.577, i64 32
  %.592.fca.4.load = load ptr, ptr %sunkaddr70, align 8
  %sunkaddr71 = getelementptr inbounds i8, ptr %.577, i64 40
  %.592.fca.5.0.load = load i64, ptr %sunkaddr71, align 8
  %sunkaddr72 = getelementptr inbounds i8, ptr %.577, i64 48
  %.592.fca.6.0.load = load i64, ptr %sunkaddr72, align 8
  %.599 = load ptr, ptr %.24, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(56) %.600, i8 0, i64 56, i1 false)
  %.604 = call i32 @NRT_adapt_ndarray_from_python(ptr %.599, ptr nonnull %.600)
  %sunkaddr73 = getelementptr inbounds i8, ptr %.600, i64 24
  %.608 = load i64, ptr %sunkaddr73, align 8
  %.609 = icmp ne i64 %.608, 8
  %.610 = icmp ne i32 %.604, 0
  %.611 = or i1 %.610, %.609
  br i1 %.611, label %entry.endif.endif.endif.e...endif.9.endif.thread, label %entry.endif.endif.endif.e...endif.9.endif.endif, !prof !0

arg18.err:                                        ; preds = %entry.endif.endif.endif.e...endif.9.endif.thread, %arg19.err
  call void @NRT_decref(ptr %.592.fca.0.load)
  br label %arg17.err

entry.endif.endif.endif.e...endif.9.endif.thread: ; preds = %entry.endif.endif.endif.e...endif.9
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %arg18.err

entry.endif.endif.endif.e...endif.9.endif.endif:  ; preds = %entry.endif.endif.endif.e...endif.9
  %.615.fca.0.load = load ptr, ptr %.600, align 8
  %sunkaddr74 = getelementptr inbounds i8, ptr %.600, i64 8
  %.615.fca.1.load = load ptr, ptr %sunkaddr74, align 8
  %sunkaddr75 = getelementptr inbounds i8, ptr %.600, i64 16
  %.615.fca.2.load = load i64, ptr %sunkaddr75, align 8
  %sunkaddr76 = getelementptr inbounds i8, ptr %.600, i64 32
  %.615.fca.4.load = load ptr, ptr %sunkaddr76, align 8
  %sunkaddr77 = getelementptr inbounds i8, ptr %.600, i64 40
  %.615.fca.5.0.load = load i64, ptr %sunkaddr77, align 8
  %sunkaddr78 = getelementptr inbounds i8, ptr %.600, i64 48
  %.615.fca.6.0.load = load i64, ptr %sunkaddr78, align 8
  %.622 = load ptr, ptr %.25, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.623, i8 0, i64 72, i1 false)
  %.627 = call i32 @NRT_adapt_ndarray_from_python(ptr %.622, ptr nonnull %.623)
  %sunkaddr79 = getelementptr inbounds i8, ptr %.623, i64 24
  %.631 = load i64, ptr %sunkaddr79, align 8
  %.632 = icmp ne i64 %.631, 8
  %.633 = icmp ne i32 %.627, 0
  %.634 = or i1 %.633, %.632
  br i1 %.634, label %entry.endif.endif.endif.e...endif.9.endif.endif.if, label %entry.endif.endif.endif.e...endif.9.endif.endif.endif, !prof !0

arg19.err:                                        ; preds = %entry.endif.endif.endif.e...endif.9.endif.endif.endif, %entry.endif.endif.endif.e...endif.10.if
  call void @NRT_decref(ptr %.615.fca.0.load)
  br label %arg18.err

entry.endif.endif.endif.e...endif.9.endif.endif.if: ; preds = %entry.endif.endif.endif.e...endif.9.endif.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  br label %entry.endif.endif.endif.e...endif.9.endif.endif.endif

entry.endif.endif.endif.e...endif.9.endif.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.9.endif.endif.if, %entry.endif.endif.endif.e...endif.9.endif.endif
  %.638.fca.0.load = load ptr, ptr %.623, align 8
  %sunkaddr80 = getelementptr inbounds i8, ptr %.623, i64 8
  %.638.fca.1.load = load ptr, ptr %sunkaddr80, align 8
  %sunkaddr81 = getelementptr inbounds i8, ptr %.623, i64 32
  %.638.fca.4.load = load ptr, ptr %sunkaddr81, align 8
  %sunkaddr82 = getelementptr inbounds i8, ptr %.623, i64 40
  %.638.fca.5.0.load = load i64, ptr %sunkaddr82, align 8
  %sunkaddr83 = getelementptr inbounds i8, ptr %.623, i64 48
  %.638.fca.5.1.load = load i64, ptr %sunkaddr83, align 8
  %sunkaddr84 = getelementptr inbounds i8, ptr %.623, i64 64
  %.638.fca.6.1.load = load i64, ptr %sunkaddr84, align 8
  br i1 %.634, label %arg19.err, label %entry.endif.endif.endif.e...endif.10, !prof !0

entry.endif.endif.endif.e...endif.10:             ; preds = %entry.endif.endif.endif.e...endif.9.endif.endif.endif
  %.647 = load ptr, ptr %.26, align 8
  call void @llvm.memset.p0.i64(ptr noundef nonnull align 8 dereferenceable(72) %.648, i8 0, i64 72, i1 false)
  %.652 = call i32 @NRT_adapt_ndarray_from_python(ptr %.647, ptr nonnull %.648)
  %sunkaddr85 = getelementptr inbounds i8, ptr %.648, i64 24
  %.656 = load i64, ptr %sunkaddr85, align 8
  %.657 = icmp ne i64 %.656, 8
  %.658 = icmp ne i32 %.652, 0
  %.659 = or i1 %.658, %.657
  br i1 %.659, label %entry.endif.endif.endif.e...endif.10.if, label %entry.endif.endif.endif.e...endif.10.endif.endif, !prof !0

entry.endif.endif.endif.e...endif.10.if:          ; preds = %entry.endif.endif.endif.e...endif.10
  call void @PyErr_SetString(ptr nonnull @PyExc_TypeError, ptr nonnull @".const.can't unbox array from PyObject into native value.  The object maybe of a different type")
  call void @NRT_decref(ptr %.638.fca.0.load)
  br label %arg19.err

entry.endif.endif.endif.e...endif.10.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.10
  %.663.fca.0.load = load ptr, ptr %.648, align 8
  %sunkaddr86 = getelementptr inbounds i8, ptr %.648, i64 8
  %.663.fca.1.load = load ptr, ptr %sunkaddr86, align 8
  %sunkaddr87 = getelementptr inbounds i8, ptr %.648, i64 32
  %.663.fca.4.load = load ptr, ptr %sunkaddr87, align 8
  %sunkaddr88 = getelementptr inbounds i8, ptr %.648, i64 40
  %.663.fca.5.0.load = load i64, ptr %sunkaddr88, align 8
  %sunkaddr89 = getelementptr inbounds i8, ptr %.648, i64 48
  %.663.fca.5.1.load = load i64, ptr %sunkaddr89, align 8
  %sunkaddr90 = getelementptr inbounds i8, ptr %.648, i64 64
  %.663.fca.6.1.load = load i64, ptr %sunkaddr90, align 8
  store i64 0, ptr %.672, align 8
  %.722 = call i32 @_ZN6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE(ptr nonnull %.672, ptr nonnull %excinfo, ptr %.57, ptr %.39, ptr %.77, ptr %.103, ptr %.85, ptr %.123, ptr %.149, ptr %.131, ptr %.169, ptr %.195, ptr %.177, ptr %.215, ptr %.241, ptr %.223, ptr %.261, ptr %.285.fca.0.load, ptr %.285.fca.1.load, i64 %.285.fca.2.load, i64 8, ptr %.285.fca.4.load, i64 %.285.fca.5.0.load, i64 %.285.fca.6.0.load, ptr %.308.fca.0.load, ptr %.308.fca.1.load, i64 %.308.fca.2.load, i64 8, ptr %.308.fca.4.load, i64 %.308.fca.5.0.load, i64 %.308.fca.6.0.load, ptr %.331.fca.0.load, ptr %.331.fca.1.load, i64 %.331.fca.2.load, i64 8, ptr %.331.fca.4.load, i64 %.331.fca.5.0.load, i64 %.331.fca.6.0.load, ptr %.354.fca.0.load, ptr poison, i64 poison, i64 poison, ptr %.354.fca.4.load, i64 poison, i64 poison, ptr %.377.fca.0.load, ptr poison, i64 poison, i64 poison, ptr %.377.fca.4.load, i64 poison, i64 poison, ptr %.400.fca.0.load, ptr poison, i64 %.400.fca.2.load, i64 poison, ptr %.400.fca.4.load, i64 %.400.fca.5.0.load, i64 poison, ptr %.423.fca.0.load, ptr poison, i64 poison, i64 poison, ptr %.423.fca.4.load, i64 %.423.fca.5.0.load, i64 poison, ptr %.446.fca.0.load, ptr %.446.fca.1.load, i64 poison, i64 8, ptr %.446.fca.4.load, i64 %.446.fca.5.0.load, i64 %.446.fca.5.1.load, i64 poison, i64 %.446.fca.6.1.load, ptr %.471.fca.0.load, ptr %.471.fca.1.load, i64 %.471.fca.2.load, i64 8, ptr %.471.fca.4.load, i64 %.471.fca.5.0.load, i64 %.471.fca.5.1.load, i64 %.471.fca.6.0.load, i64 %.471.fca.6.1.load, ptr %.496.fca.0.load, ptr poison, i64 poison, i64 poison, ptr %.496.fca.4.load, i64 poison, i64 poison, ptr %.519.fca.0.load, ptr %.519.fca.1.load, i64 %.519.fca.2.load, i64 8, ptr %.519.fca.4.load, i64 %.519.fca.5.0.load, i64 %.519.fca.5.1.load, i64 %.519.fca.6.0.load, i64 %.519.fca.6.1.load, ptr %.544.fca.0.load, ptr %.544.fca.1.load, i64 %.544.fca.2.load, i64 8, ptr %.544.fca.4.load, i64 %.544.fca.5.0.load, i64 %.544.fca.5.1.load, i64 %.544.fca.6.0.load, i64 %.544.fca.6.1.load, ptr %.569.fca.0.load, ptr %.569.fca.1.load, i64 %.569.fca.2.load, i64 8, ptr %.569.fca.4.load, i64 %.569.fca.5.0.load, i64 %.569.fca.6.0.load, ptr %.592.fca.0.load, ptr %.592.fca.1.load, i64 %.592.fca.2.load, i64 8, ptr %.592.fca.4.load, i64 %.592.fca.5.0.load, i64 %.592.fca.6.0.load, ptr %.615.fca.0.load, ptr %.615.fca.1.load, i64 %.615.fca.2.load, i64 8, ptr %.615.fca.4.load, i64 %.615.fca.5.0.load, i64 %.615.fca.6.0.load, ptr %.638.fca.0.load, ptr %.638.fca.1.load, i64 poison, i64 8, ptr %.638.fca.4.load, i64 %.638.fca.5.0.load, i64 %.638.fca.5.1.load, i64 poison, i64 %.638.fca.6.1.load, ptr %.663.fca.0.load, ptr %.663.fca.1.load, i64 poison, i64 8, ptr %.663.fca.4.load, i64 %.663.fca.5.0.load, i64 %.663.fca.5.1.load, i64 poison, i64 %.663.fca.6.1.load) #3
  %.723 = load ptr, ptr %excinfo, align 8
  %.732 = load i64, ptr %.672, align 8
  call void @NRT_decref(ptr %.285.fca.0.load)
  call void @NRT_decref(ptr %.308.fca.0.load)
  call void @NRT_decref(ptr %.331.fca.0.load)
  call void @NRT_decref(ptr %.354.fca.0.load)
  call void @NRT_decref(ptr %.377.fca.0.load)
  call void @NRT_decref(ptr %.400.fca.0.load)
  call void @NRT_decref(ptr %.423.fca.0.load)
  call void @NRT_decref(ptr %.446.fca.0.load)
  call void @NRT_decref(ptr %.471.fca.0.load)
  call void @NRT_decref(ptr %.496.fca.0.load)
  call void @NRT_decref(ptr %.519.fca.0.load)
  call void @NRT_decref(ptr %.544.fca.0.load)
  call void @NRT_decref(ptr %.569.fca.0.load)
  call void @NRT_decref(ptr %.592.fca.0.load)
  call void @NRT_decref(ptr %.615.fca.0.load)
  call void @NRT_decref(ptr %.638.fca.0.load)
  call void @NRT_decref(ptr %.663.fca.0.load)
  %cond = icmp eq i32 %.722, 0
  br i1 %cond, label %entry.endif.endif.endif.e...endif.11, label %entry.endif.endif.endif.e...endif.10.endif.endif.endif, !prof !1

entry.endif.endif.endif.e...endif.10.endif.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.10.endif.endif
  %.730 = icmp sgt i32 %.722, 0
  br i1 %.730, label %entry.endif.endif.endif.e...if.12, label %entry.endif.endif.endif.e...endif.12

entry.endif.endif.endif.e...endif.11:             ; preds = %entry.endif.endif.endif.e...endif.10.endif.endif
  %.802 = call ptr @PyLong_FromLongLong(i64 %.732)
  br label %common.ret

entry.endif.endif.endif.e...if.12:                ; preds = %entry.endif.endif.endif.e...endif.10.endif.endif.endif
  call void @PyErr_Clear()
  %.809 = load { ptr, i32, ptr, ptr, i32 }, ptr %.723, align 8
  %.810 = extractvalue { ptr, i32, ptr, ptr, i32 } %.809, 4
  %.811 = icmp sgt i32 %.810, 0
  %.814 = extractvalue { ptr, i32, ptr, ptr, i32 } %.809, 0
  %.816 = extractvalue { ptr, i32, ptr, ptr, i32 } %.809, 1
  br i1 %.811, label %entry.endif.endif.endif.e...if.12.if, label %entry.endif.endif.endif.e...if.12.else

entry.endif.endif.endif.e...endif.12:             ; preds = %entry.endif.endif.endif.e...endif.10.endif.endif.endif
  switch i32 %.722, label %entry.endif.endif.endif.e...endif.12.endif.endif [
    i32 -3, label %entry.endif.endif.endif.e...endif.12.if
    i32 -1, label %common.ret
  ]

entry.endif.endif.endif.e...if.12.if:             ; preds = %entry.endif.endif.endif.e...if.12
  %.817 = sext i32 %.816 to i64
  %.818 = call ptr @PyBytes_FromStringAndSize(ptr %.814, i64 %.817)
  %.819 = load { ptr, i32, ptr, ptr, i32 }, ptr %.723, align 8
  %.820 = extractvalue { ptr, i32, ptr, ptr, i32 } %.819, 2
  %.822 = extractvalue { ptr, i32, ptr, ptr, i32 } %.819, 3
  %.824 = call ptr %.822(ptr %.820)
  %.825 = icmp eq ptr %.824, null
  br i1 %.825, label %entry.endif.endif.endif.e...if.12.if.if, label %entry.endif.endif.endif.e...if.12.if.endif, !prof !0

entry.endif.endif.endif.e...if.12.else:           ; preds = %entry.endif.endif.endif.e...if.12
  %.838 = extractvalue { ptr, i32, ptr, ptr, i32 } %.809, 2
  %.839 = call ptr @numba_unpickle(ptr %.814, i32 %.816, ptr %.838)
  br label %entry.endif.endif.endif.e...if.12.endif

entry.endif.endif.endif.e...if.12.endif:          ; preds = %entry.endif.endif.endif.e...if.12.if.endif, %entry.endif.endif.endif.e...if.12.else
  %.841 = phi ptr [ %.829, %entry.endif.endif.endif.e...if.12.if.endif ], [ %.839, %entry.endif.endif.endif.e...if.12.else ]
  %.842.not = icmp eq ptr %.841, null
  br i1 %.842.not, label %common.ret, label %entry.endif.endif.endif.e...if.12.endif.if, !prof !0

entry.endif.endif.endif.e...if.12.if.if:          ; preds = %entry.endif.endif.endif.e...if.12.if
  call void @PyErr_SetString(ptr nonnull @PyExc_RuntimeError, ptr nonnull @".const.Error creating Python tuple from runtime exception arguments")
  br label %common.ret

entry.endif.endif.endif.e...if.12.if.endif:       ; preds = %entry.endif.endif.endif.e...if.12.if
  %.829 = call ptr @numba_runtime_build_excinfo_struct(ptr %.818, ptr nonnull %.824)
  call void @NRT_Free(ptr nonnull %.723)
  br label %entry.endif.endif.endif.e...if.12.endif

entry.endif.endif.endif.e...if.12.endif.if:       ; preds = %entry.endif.endif.endif.e...if.12.endif
  call void @numba_do_raise(ptr nonnull %.841)
  br label %common.ret

entry.endif.endif.endif.e...endif.12.if:          ; preds = %entry.endif.endif.endif.e...endif.12
  call void @PyErr_SetNone(ptr nonnull @PyExc_StopIteration)
  br label %common.ret

entry.endif.endif.endif.e...endif.12.endif.endif: ; preds = %entry.endif.endif.endif.e...endif.12
  call void @PyErr_SetString(ptr nonnull @PyExc_SystemError, ptr nonnull @".const.unknown error when calling native function")
  br label %common.ret
}

declare i32 @PyArg_UnpackTuple(ptr, ptr, i64, i64, ...) local_unnamed_addr

declare void @PyErr_SetString(ptr, ptr) local_unnamed_addr

declare i32 @NRT_adapt_ndarray_from_python(ptr captures(none), ptr captures(none)) local_unnamed_addr

declare ptr @PyLong_FromLongLong(i64) local_unnamed_addr

declare void @PyErr_Clear() local_unnamed_addr

declare ptr @PyBytes_FromStringAndSize(ptr, i64) local_unnamed_addr

declare ptr @numba_runtime_build_excinfo_struct(ptr, ptr) local_unnamed_addr

declare void @NRT_Free(ptr) local_unnamed_addr

declare void @numba_do_raise(ptr) local_unnamed_addr

declare void @PyErr_SetNone(ptr) local_unnamed_addr

define i64 @cfunc._ZN6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE({ ptr, ptr, ptr } %.1, { ptr, ptr, ptr } %.2, { ptr, ptr, ptr } %.3, { ptr, ptr, ptr } %.4, { ptr, ptr, ptr } %.5, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.9, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.10, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.11, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.12, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.15, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22) local_unnamed_addr {
entry:
  %.24 = alloca i64, align 8
  store i64 0, ptr %.24, align 8
  %excinfo = alloca ptr, align 8
  store ptr null, ptr %excinfo, align 8
  %extracted.c_addr = extractvalue { ptr, ptr, ptr } %.1, 0
  %extracted.py_addr = extractvalue { ptr, ptr, ptr } %.1, 1
  %extracted.jit_addr = extractvalue { ptr, ptr, ptr } %.1, 2
  %extracted.c_addr.1 = extractvalue { ptr, ptr, ptr } %.2, 0
  %extracted.py_addr.1 = extractvalue { ptr, ptr, ptr } %.2, 1
  %extracted.jit_addr.1 = extractvalue { ptr, ptr, ptr } %.2, 2
  %extracted.c_addr.2 = extractvalue { ptr, ptr, ptr } %.3, 0
  %extracted.py_addr.2 = extractvalue { ptr, ptr, ptr } %.3, 1
  %extracted.jit_addr.2 = extractvalue { ptr, ptr, ptr } %.3, 2
  %extracted.c_addr.3 = extractvalue { ptr, ptr, ptr } %.4, 0
  %extracted.py_addr.3 = extractvalue { ptr, ptr, ptr } %.4, 1
  %extracted.jit_addr.3 = extractvalue { ptr, ptr, ptr } %.4, 2
  %extracted.c_addr.4 = extractvalue { ptr, ptr, ptr } %.5, 0
  %extracted.py_addr.4 = extractvalue { ptr, ptr, ptr } %.5, 1
  %extracted.jit_addr.4 = extractvalue { ptr, ptr, ptr } %.5, 2
  %extracted.meminfo = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 0
  %extracted.parent = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 1
  %extracted.nitems = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 2
  %extracted.itemsize = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 3
  %extracted.data = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 4
  %extracted.shape = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 5
  %.28 = extractvalue [1 x i64] %extracted.shape, 0
  %extracted.strides = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.6, 6
  %.29 = extractvalue [1 x i64] %extracted.strides, 0
  %extracted.meminfo.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 0
  %extracted.parent.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 1
  %extracted.nitems.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 2
  %extracted.itemsize.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 3
  %extracted.data.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 4
  %extracted.shape.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 5
  %.30 = extractvalue [1 x i64] %extracted.shape.1, 0
  %extracted.strides.1 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.7, 6
  %.31 = extractvalue [1 x i64] %extracted.strides.1, 0
  %extracted.meminfo.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 0
  %extracted.parent.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 1
  %extracted.nitems.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 2
  %extracted.itemsize.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 3
  %extracted.data.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 4
  %extracted.shape.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 5
  %.32 = extractvalue [1 x i64] %extracted.shape.2, 0
  %extracted.strides.2 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.8, 6
  %.33 = extractvalue [1 x i64] %extracted.strides.2, 0
  %extracted.meminfo.3 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.9, 0
  %extracted.data.3 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.9, 4
  %extracted.meminfo.4 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.10, 0
  %extracted.data.4 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.10, 4
  %extracted.meminfo.5 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.11, 0
  %extracted.nitems.5 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.11, 2
  %extracted.data.5 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.11, 4
  %extracted.shape.5 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.11, 5
  %.38 = extractvalue [1 x i64] %extracted.shape.5, 0
  %extracted.meminfo.6 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.12, 0
  %extracted.data.6 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.12, 4
  %extracted.shape.6 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.12, 5
  %.40 = extractvalue [1 x i64] %extracted.shape.6, 0
  %extracted.meminfo.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 0
  %extracted.parent.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 1
  %extracted.itemsize.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 3
  %extracted.data.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 4
  %extracted.shape.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 5
  %.42 = extractvalue [2 x i64] %extracted.shape.7, 0
  %.43 = extractvalue [2 x i64] %extracted.shape.7, 1
  %extracted.strides.7 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.13, 6
  %.45 = extractvalue [2 x i64] %extracted.strides.7, 1
  %extracted.meminfo.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 0
  %extracted.parent.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 1
  %extracted.nitems.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 2
  %extracted.itemsize.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 3
  %extracted.data.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 4
  %extracted.shape.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 5
  %.46 = extractvalue [2 x i64] %extracted.shape.8, 0
  %.47 = extractvalue [2 x i64] %extracted.shape.8, 1
  %extracted.strides.8 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.14, 6
  %.48 = extractvalue [2 x i64] %extracted.strides.8, 0
  %.49 = extractvalue [2 x i64] %extracted.strides.8, 1
  %extracted.meminfo.9 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.15, 0
  %extracted.data.9 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.15, 4
  %extracted.meminfo.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 0
  %extracted.parent.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 1
  %extracted.nitems.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 2
  %extracted.itemsize.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 3
  %extracted.data.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 4
  %extracted.shape.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 5
  %.52 = extractvalue [2 x i64] %extracted.shape.10, 0
  %.53 = extractvalue [2 x i64] %extracted.shape.10, 1
  %extracted.strides.10 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.16, 6
  %.54 = extractvalue [2 x i64] %extracted.strides.10, 0
  %.55 = extractvalue [2 x i64] %extracted.strides.10, 1
  %extracted.meminfo.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 0
  %extracted.parent.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 1
  %extracted.nitems.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 2
  %extracted.itemsize.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 3
  %extracted.data.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 4
  %extracted.shape.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 5
  %.56 = extractvalue [2 x i64] %extracted.shape.11, 0
  %.57 = extractvalue [2 x i64] %extracted.shape.11, 1
  %extracted.strides.11 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.17, 6
  %.58 = extractvalue [2 x i64] %extracted.strides.11, 0
  %.59 = extractvalue [2 x i64] %extracted.strides.11, 1
  %extracted.meminfo.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 0
  %extracted.parent.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 1
  %extracted.nitems.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 2
  %extracted.itemsize.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 3
  %extracted.data.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 4
  %extracted.shape.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 5
  %.60 = extractvalue [1 x i64] %extracted.shape.12, 0
  %extracted.strides.12 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.18, 6
  %.61 = extractvalue [1 x i64] %extracted.strides.12, 0
  %extracted.meminfo.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 0
  %extracted.parent.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 1
  %extracted.nitems.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 2
  %extracted.itemsize.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 3
  %extracted.data.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 4
  %extracted.shape.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 5
  %.62 = extractvalue [1 x i64] %extracted.shape.13, 0
  %extracted.strides.13 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.19, 6
  %.63 = extractvalue [1 x i64] %extracted.strides.13, 0
  %extracted.meminfo.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 0
  %extracted.parent.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 1
  %extracted.nitems.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 2
  %extracted.itemsize.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 3
  %extracted.data.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 4
  %extracted.shape.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 5
  %.64 = extractvalue [1 x i64] %extracted.shape.14, 0
  %extracted.strides.14 = extractvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.20, 6
  %.65 = extractvalue [1 x i64] %extracted.strides.14, 0
  %extracted.meminfo.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 0
  %extracted.parent.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 1
  %extracted.itemsize.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 3
  %extracted.data.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 4
  %extracted.shape.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 5
  %.66 = extractvalue [2 x i64] %extracted.shape.15, 0
  %.67 = extractvalue [2 x i64] %extracted.shape.15, 1
  %extracted.strides.15 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.21, 6
  %.69 = extractvalue [2 x i64] %extracted.strides.15, 1
  %extracted.meminfo.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 0
  %extracted.parent.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 1
  %extracted.itemsize.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 3
  %extracted.data.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 4
  %extracted.shape.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 5
  %.70 = extractvalue [2 x i64] %extracted.shape.16, 0
  %.71 = extractvalue [2 x i64] %extracted.shape.16, 1
  %extracted.strides.16 = extractvalue { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] } %.22, 6
  %.73 = extractvalue [2 x i64] %extracted.strides.16, 1
  %.74 = call i32 @_ZN6charts7solvers4loop6_driveB3v72B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d140FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_29_5d190FunctionType_5bint64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20float64_2c_20array_28float64_2c_202d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d179FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28int64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIxLi2E1C7mutable7alignedE(ptr nonnull %.24, ptr nonnull %excinfo, ptr %extracted.c_addr, ptr %extracted.py_addr, ptr %extracted.jit_addr, ptr %extracted.c_addr.1, ptr %extracted.py_addr.1, ptr %extracted.jit_addr.1, ptr %extracted.c_addr.2, ptr %extracted.py_addr.2, ptr %extracted.jit_addr.2, ptr %extracted.c_addr.3, ptr %extracted.py_addr.3, ptr %extracted.jit_addr.3, ptr %extracted.c_addr.4, ptr %extracted.py_addr.4, ptr %extracted.jit_addr.4, ptr %extracted.meminfo, ptr %extracted.parent, i64 %extracted.nitems, i64 %extracted.itemsize, ptr %extracted.data, i64 %.28, i64 %.29, ptr %extracted.meminfo.1, ptr %extracted.parent.1, i64 %extracted.nitems.1, i64 %extracted.itemsize.1, ptr %extracted.data.1, i64 %.30, i64 %.31, ptr %extracted.meminfo.2, ptr %extracted.parent.2, i64 %extracted.nitems.2, i64 %extracted.itemsize.2, ptr %extracted.data.2, i64 %.32, i64 %.33, ptr %extracted.meminfo.3, ptr poison, i64 poison, i64 poison, ptr %extracted.data.3, i64 poison, i64 poison, ptr %extracted.meminfo.4, ptr poison, i64 poison, i64 poison, ptr %extracted.data.4, i64 poison, i64 poison, ptr %extracted.meminfo.5, ptr poison, i64 %extracted.nitems.5, i64 poison, ptr %extracted.data.5, i64 %.38, i64 poison, ptr %extracted.meminfo.6, ptr poison, i64 poison, i64 poison, ptr %extracted.data.6, i64 %.40, i64 poison, ptr %extracted.meminfo.7, ptr %extracted.parent.7, i64 poison, i64 %extracted.itemsize.7, ptr %extracted.data.7, i64 %.42, i64 %.43, i64 poison, i64 %.45, ptr %extracted.meminfo.8, ptr %extracted.parent.8, i64 %extracted.nitems.8, i64 %extracted.itemsize.8, ptr %extracted.data.8, i64 %.46, i64 %.47, i64 %.48, i64 %.49, ptr %extracted.meminfo.9, ptr poison, i64 poison, i64 poison, ptr %extracted.data.9, i64 poison, i64 poison, ptr %extracted.meminfo.10, ptr %extracted.parent.10, i64 %extracted.nitems.10, i64 %extracted.itemsize.10, ptr %extracted.data.10, i64 %.52, i64 %.53, i64 %.54, i64 %.55, ptr %extracted.meminfo.11, ptr %extracted.parent.11, i64 %extracted.nitems.11, i64 %extracted.itemsize.11, ptr %extracted.data.11, i64 %.56, i64 %.57, i64 %.58, i64 %.59, ptr %extracted.meminfo.12, ptr %extracted.parent.12, i64 %extracted.nitems.12, i64 %extracted.itemsize.12, ptr %extracted.data.12, i64 %.60, i64 %.61, ptr %extracted.meminfo.13, ptr %extracted.parent.13, i64 %extracted.nitems.13, i64 %extracted.itemsize.13, ptr %extracted.data.13, i64 %.62, i64 %.63, ptr %extracted.meminfo.14, ptr %extracted.parent.14, i64 %extracted.nitems.14, i64 %extracted.itemsize.14, ptr %extracted.data.14, i64 %.64, i64 %.65, ptr %extracted.meminfo.15, ptr %extracted.parent.15, i64 poison, i64 %extracted.itemsize.15, ptr %extracted.data.15, i64 %.66, i64 %.67, i64 poison, i64 %.69, ptr %extracted.meminfo.16, ptr %extracted.parent.16, i64 poison, i64 %extracted.itemsize.16, ptr %extracted.data.16, i64 %.70, i64 %.71, i64 poison, i64 %.73) #3
  %.75 = load ptr, ptr %excinfo, align 8
  %.84 = load i64, ptr %.24, align 8
  %.86 = alloca i32, align 4
  store i32 0, ptr %.86, align 4
  %cond = icmp eq i32 %.74, 0
  br i1 %cond, label %common.ret, label %entry.if, !prof !1

entry.if:                                         ; preds = %entry
  %.82 = icmp sgt i32 %.74, 0
  call void @numba_gil_ensure(ptr nonnull %.86)
  br i1 %.82, label %entry.if.if, label %entry.if.endif

common.ret:                                       ; preds = %entry, %.89, %entry.if.if.if.if
  %common.ret.op = phi i64 [ 0, %entry.if.if.if.if ], [ %.84, %.89 ], [ %.84, %entry ]
  ret i64 %common.ret.op

.89:                                              ; preds = %entry.if.endif, %entry.if.if.endif, %entry.if.if.endif.if, %entry.if.endif.endif.endif, %entry.if.endif.if
  %.137 = call ptr @PyUnicode_FromString(ptr nonnull @".const.<numba.core.cpu.CPUContext>")
  call void @PyErr_WriteUnraisable(ptr %.137)
  call void @Py_DecRef(ptr %.137)
  call void @numba_gil_release(ptr nonnull %.86)
  br label %common.ret

entry.if.if:                                      ; preds = %entry.if
  call void @PyErr_Clear()
  %.92 = load { ptr, i32, ptr, ptr, i32 }, ptr %.75, align 8
  %.93 = extractvalue { ptr, i32, ptr, ptr, i32 } %.92, 4
  %.94 = icmp sgt i32 %.93, 0
  %.97 = extractvalue { ptr, i32, ptr, ptr, i32 } %.92, 0
  %.99 = extractvalue { ptr, i32, ptr, ptr, i32 } %.92, 1
  br i1 %.94, label %entry.if.if.if, label %entry.if.if.else

entry.if.endif:                                   ; preds = %entry.if
  switch i32 %.74, label %entry.if.endif.endif.endif [
    i32 -3, label %entry.if.endif.if
    i32 -1, label %.89
  ]

entry.if.if.if:                                   ; preds = %entry.if.if
  %.100 = sext i32 %.99 to i64
  %.101 = call ptr @PyBytes_FromStringAndSize(ptr %.97, i64 %.100)
  %.102 = load { ptr, i32, ptr, ptr, i32 }, ptr %.75, align 8
  %.103 = extractvalue { ptr, i32, ptr, ptr, i32 } %.102, 2
  %.105 = extractvalue { ptr, i32, ptr, ptr, i32 } %.102, 3
  %.107 = call ptr %.105(ptr %.103)
  %.108 = icmp eq ptr %.107, null
  br i1 %.108, label %entry.if.if.if.if, label %entry.if.if.if.endif, !prof !0

entry.if.if.else:                                 ; preds = %entry.if.if
  %.121 = extractvalue { ptr, i32, ptr, ptr, i32 } %.92, 2
  %.122 = call ptr @numba_unpickle(ptr %.97, i32 %.99, ptr %.121)
  br label %entry.if.if.endif

entry.if.if.endif:                                ; preds = %entry.if.if.if.endif, %entry.if.if.else
  %.124 = phi ptr [ %.112, %entry.if.if.if.endif ], [ %.122, %entry.if.if.else ]
  %.125.not = icmp eq ptr %.124, null
  br i1 %.125.not, label %.89, label %entry.if.if.endif.if, !prof !0

entry.if.if.if.if:                                ; preds = %entry.if.if.if
  call void @PyErr_SetString(ptr nonnull @PyExc_RuntimeError, ptr nonnull @".const.Error creating Python tuple from runtime exception arguments.11")
  br label %common.ret

entry.if.if.if.endif:                             ; preds = %entry.if.if.if
  %.112 = call ptr @numba_runtime_build_excinfo_struct(ptr %.101, ptr nonnull %.107)
  call void @NRT_Free(ptr nonnull %.75)
  br label %entry.if.if.endif

entry.if.if.endif.if:                             ; preds = %entry.if.if.endif
  call void @numba_do_raise(ptr nonnull %.124)
  br label %.89

entry.if.endif.if:                                ; preds = %entry.if.endif
  call void @PyErr_SetNone(ptr nonnull @PyExc_StopIteration)
  br label %.89

entry.if.endif.endif.endif:                       ; preds = %entry.if.endif
  call void @PyErr_SetString(ptr nonnull @PyExc_SystemError, ptr nonnull @".const.unknown error when calling native function.12")
  br label %.89
}

declare ptr @PyUnicode_FromString(ptr) local_unnamed_addr

declare void @PyErr_WriteUnraisable(ptr) local_unnamed_addr

define linkonce_odr range(i32 -1, -2) i32 @_ZN6charts7solvers2rk8rk4_stepB3v74B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMVC_2fAwA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.f.0, ptr %arg.f.1, ptr readonly captures(address_is_null) %arg.f.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr readnone captures(none) %arg.ynew.0, ptr readnone captures(none) %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr writeonly captures(none) %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0) local_unnamed_addr {
B0:
  %.90 = alloca { ptr, ptr, i64, i64, ptr, [2 x i64], [2 x i64] }, align 8
  %.fca.1.gep = getelementptr inbounds nuw i8, ptr %.90, i64 8
  %.fca.2.gep = getelementptr inbounds nuw i8, ptr %.90, i64 16
  %.fca.3.gep = getelementptr inbounds nuw i8, ptr %.90, i64 24
  %.fca.4.gep = getelementptr inbounds nuw i8, ptr %.90, i64 32
  %.fca.5.0.gep = getelementptr inbounds nuw i8, ptr %.90, i64 40
  %.fca.5.1.gep = getelementptr inbounds nuw i8, ptr %.90, i64 48
  %.fca.6.0.gep = getelementptr inbounds nuw i8, ptr %.90, i64 56
  %.fca.6.1.gep = getelementptr inbounds nuw i8, ptr %.90, i64 64
  %.94 = alloca [1 x i64], align 8
  %.150 = alloca [1 x i64], align 8
  store i64 0, ptr %.150, align 8
  %.296 = alloca i32, align 4
  store i32 0, ptr %.296, align 4
  %.331 = alloca double, align 8
  store double 0.000000e+00, ptr %.331, align 8
  %excinfo.2 = alloca ptr, align 8
  store ptr null, ptr %excinfo.2, align 8
  %.854 = alloca i32, align 4
  store i32 0, ptr %.854, align 4
  %.889 = alloca double, align 8
  store double 0.000000e+00, ptr %.889, align 8
  %excinfo.3 = alloca ptr, align 8
  store ptr null, ptr %excinfo.3, align 8
  store ptr %arg.K.0, ptr %.90, align 8
  store ptr %arg.K.1, ptr %.fca.1.gep, align 8
  store i64 %arg.K.2, ptr %.fca.2.gep, align 8
  store i64 %arg.K.3, ptr %.fca.3.gep, align 8
  store ptr %arg.K.4, ptr %.fca.4.gep, align 8
  store i64 %arg.K.5.0, ptr %.fca.5.0.gep, align 8
  store i64 %arg.K.5.1, ptr %.fca.5.1.gep, align 8
  store i64 %arg.K.6.0, ptr %.fca.6.0.gep, align 8
  store i64 %arg.K.6.1, ptr %.fca.6.1.gep, align 8
  store i64 %arg.K.2, ptr %.94, align 8
  %.71.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.y.0, 0
  %.71.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.0.insert, ptr %arg.y.1, 1
  %.71.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.1.insert, i64 %arg.y.2, 2
  %.71.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.2.insert, i64 %arg.y.3, 3
  %.71.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.3.insert, ptr %arg.y.4, 4
  %.71.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.4.insert, i64 %arg.y.5.0, 5, 0
  %.71.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.5.0.insert, i64 %arg.y.6.0, 6, 0
  %.160 = call i32 @numba_attempt_nocopy_reshape(i64 2, ptr nonnull %.fca.5.0.gep, ptr nonnull %.fca.6.0.gep, i64 1, ptr nonnull %.94, ptr nonnull %.150, i64 %arg.K.3, i32 0)
  %.161 = icmp eq i32 %.160, 0
  br i1 %.161, label %B0.endif.if, label %B0.endif.endif

B13409633:                                        ; preds = %B13409633.preheader29, %B13409633
  %.632619621 = phi i64 [ %.639.7, %B13409633 ], [ %.632619621.unr, %B13409633.preheader29 ]
  %sunkaddr768 = mul i64 %.632619621, 8
  %sunkaddr769 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr768
  %.691 = load double, ptr %sunkaddr769, align 8
  %sunkaddr770 = mul i64 %.632619621, 8
  %sunkaddr771 = getelementptr i8, ptr %.172, i64 %sunkaddr770
  %.720 = load double, ptr %sunkaddr771, align 8
  %.722 = fmul double %.524.us.us, %.720
  %.723 = fadd double %.691, %.722
  %sunkaddr = mul i64 %.632619621, 8
  %sunkaddr772 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr
  store double %.723, ptr %sunkaddr772, align 8
  %sunkaddr773 = mul i64 %.632619621, 8
  %sunkaddr774 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr773
  %sunkaddr775 = getelementptr i8, ptr %sunkaddr774, i64 8
  %.691.1481 = load double, ptr %sunkaddr775, align 8
  %sunkaddr776 = mul i64 %.632619621, 8
  %sunkaddr777 = getelementptr i8, ptr %.172, i64 %sunkaddr776
  %sunkaddr778 = getelementptr i8, ptr %sunkaddr777, i64 8
  %.720.1483 = load double, ptr %sunkaddr778, align 8
  %.722.1484 = fmul double %.524.us.us, %.720.1483
  %.723.1485 = fadd double %.691.1481, %.722.1484
  %sunkaddr779 = mul i64 %.632619621, 8
  %sunkaddr780 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr779
  %sunkaddr781 = getelementptr i8, ptr %sunkaddr780, i64 8
  store double %.723.1485, ptr %sunkaddr781, align 8
  %sunkaddr782 = mul i64 %.632619621, 8
  %sunkaddr783 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr782
  %sunkaddr784 = getelementptr i8, ptr %sunkaddr783, i64 16
  %.691.2491 = load double, ptr %sunkaddr784, align 8
  %sunkaddr785 = mul i64 %.632619621, 8
  %sunkaddr786 = getelementptr i8, ptr %.172, i64 %sunkaddr785
  %sunkaddr787 = getelementptr i8, ptr %sunkaddr786, i64 16
  %.720.2493 = load double, ptr %sunkaddr787, align 8
  %.722.2494 = fmul double %.524.us.us, %.720.2493
  %.723.2495 = fadd double %.691.2491, %.722.2494
  %sunkaddr788 = mul i64 %.632619621, 8
  %sunkaddr789 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr788
  %sunkaddr790 = getelementptr i8, ptr %sunkaddr789, i64 16
  store double %.723.2495, ptr %sunkaddr790, align 8
  %sunkaddr791 = mul i64 %.632619621, 8
  %sunkaddr792 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr791
  %sunkaddr793 = getelementptr i8, ptr %sunkaddr792, i64 24
  %.691.3 = load double, ptr %sunkaddr793, align 8
  %sunkaddr794 = mul i64 %.632619621, 8
  %sunkaddr795 = getelementptr i8, ptr %.172, i64 %sunkaddr794
  %sunkaddr796 = getelementptr i8, ptr %sunkaddr795, i64 24
  %.720.3 = load double, ptr %sunkaddr796, align 8
  %.722.3 = fmul double %.524.us.us, %.720.3
  %.723.3 = fadd double %.691.3, %.722.3
  %sunkaddr797 = mul i64 %.632619621, 8
  %sunkaddr798 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr797
  %sunkaddr799 = getelementptr i8, ptr %sunkaddr798, i64 24
  store double %.723.3, ptr %sunkaddr799, align 8
  %sunkaddr800 = mul i64 %.632619621, 8
  %sunkaddr801 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr800
  %sunkaddr802 = getelementptr i8, ptr %sunkaddr801, i64 32
  %.691.4 = load double, ptr %sunkaddr802, align 8
  %sunkaddr803 = mul i64 %.632619621, 8
  %sunkaddr804 = getelementptr i8, ptr %.172, i64 %sunkaddr803
  %sunkaddr805 = getelementptr i8, ptr %sunkaddr804, i64 32
  %.720.4 = load double, ptr %sunkaddr805, align 8
  %.722.4 = fmul double %.524.us.us, %.720.4
  %.723.4 = fadd double %.691.4, %.722.4
  %sunkaddr806 = mul i64 %.632619621, 8
  %sunkaddr807 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr806
  %sunkaddr808 = getelementptr i8, ptr %sunkaddr807, i64 32
  store double %.723.4, ptr %sunkaddr808, align 8
  %sunkaddr809 = mul i64 %.632619621, 8
  %sunkaddr810 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr809
  %sunkaddr811 = getelementptr i8, ptr %sunkaddr810, i64 40
  %.691.5 = load double, ptr %sunkaddr811, align 8
  %sunkaddr812 = mul i64 %.632619621, 8
  %sunkaddr813 = getelementptr i8, ptr %.172, i64 %sunkaddr812
  %sunkaddr814 = getelementptr i8, ptr %sunkaddr813, i64 40
  %.720.5 = load double, ptr %sunkaddr814, align 8
  %.722.5 = fmul double %.524.us.us, %.720.5
  %.723.5 = fadd double %.691.5, %.722.5
  %sunkaddr815 = mul i64 %.632619621, 8
  %sunkaddr816 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr815
  %sunkaddr817 = getelementptr i8, ptr %sunkaddr816, i64 40
  store double %.723.5, ptr %sunkaddr817, align 8
  %sunkaddr818 = mul i64 %.632619621, 8
  %sunkaddr819 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr818
  %sunkaddr820 = getelementptr i8, ptr %sunkaddr819, i64 48
  %.691.6 = load double, ptr %sunkaddr820, align 8
  %sunkaddr821 = mul i64 %.632619621, 8
  %sunkaddr822 = getelementptr i8, ptr %.172, i64 %sunkaddr821
  %sunkaddr823 = getelementptr i8, ptr %sunkaddr822, i64 48
  %.720.6 = load double, ptr %sunkaddr823, align 8
  %.722.6 = fmul double %.524.us.us, %.720.6
  %.723.6 = fadd double %.691.6, %.722.6
  %sunkaddr824 = mul i64 %.632619621, 8
  %sunkaddr825 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr824
  %sunkaddr826 = getelementptr i8, ptr %sunkaddr825, i64 48
  store double %.723.6, ptr %sunkaddr826, align 8
  %.639.7 = add nuw nsw i64 %.632619621, 8
  %sunkaddr827 = mul i64 %.632619621, 8
  %sunkaddr828 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr827
  %sunkaddr829 = getelementptr i8, ptr %sunkaddr828, i64 56
  %.691.7 = load double, ptr %sunkaddr829, align 8
  %sunkaddr830 = mul i64 %.632619621, 8
  %sunkaddr831 = getelementptr i8, ptr %.172, i64 %sunkaddr830
  %sunkaddr832 = getelementptr i8, ptr %sunkaddr831, i64 56
  %.720.7 = load double, ptr %sunkaddr832, align 8
  %.722.7 = fmul double %.524.us.us, %.720.7
  %.723.7 = fadd double %.691.7, %.722.7
  %sunkaddr833 = mul i64 %.632619621, 8
  %sunkaddr834 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr833
  %sunkaddr835 = getelementptr i8, ptr %sunkaddr834, i64 56
  store double %.723.7, ptr %sunkaddr835, align 8
  %exitcond.not.7 = icmp eq i64 %arg.y.2, %.639.7
  br i1 %exitcond.not.7, label %B13409637, label %B13409633, !llvm.loop !22

B13409637:                                        ; preds = %B13409633, %B13409633.prol.loopexit, %vec.epilog.middle.block, %middle.block, %B178.preheader
  %.806 = getelementptr double, ptr %arg.K.4, i64 %arg.K.5.1
  store double 0.000000e+00, ptr %.889, align 8
  %.899 = call i32 %arg.f.2(ptr nonnull %.889, ptr nonnull %excinfo.3, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.806, i64 %arg.K.5.1, i64 %arg.K.6.1)
  switch i32 %.899, label %B13409637.else.if.if [
    i32 -2, label %B13409637.endif.endif
    i32 0, label %B13409637.endif.endif
  ], !prof !4

B13409681:                                        ; preds = %B13409681.preheader565, %B13409681
  %lsr.iv = phi i64 [ 0, %B13409681.preheader565 ], [ %lsr.iv.next, %B13409681 ]
  %0 = shl i64 %lsr.iv, 3
  %scevgep618 = getelementptr i8, ptr %scevgep614, i64 %0
  %scevgep619 = getelementptr i8, ptr %scevgep618, i64 -24
  %.1160 = load double, ptr %scevgep619, align 8
  %scevgep55 = getelementptr i8, ptr %scevgep54, i64 %0
  %1 = shl i64 %lsr.iv, 3
  %scevgep60 = getelementptr i8, ptr %scevgep54, i64 %1
  %scevgep61 = getelementptr i8, ptr %scevgep60, i64 -24
  %.1187 = load double, ptr %scevgep61, align 8
  %2 = shl i64 %lsr.iv, 3
  %scevgep48 = getelementptr i8, ptr %scevgep598, i64 %2
  %scevgep53 = getelementptr i8, ptr %scevgep48, i64 -24
  %.1216 = load double, ptr %scevgep53, align 8
  %3 = shl i64 %lsr.iv, 3
  %scevgep42 = getelementptr i8, ptr %scevgep590, i64 %3
  %scevgep47 = getelementptr i8, ptr %scevgep42, i64 -24
  %.1245 = load double, ptr %scevgep47, align 8
  %4 = shl i64 %lsr.iv, 3
  %scevgep36 = getelementptr i8, ptr %scevgep582, i64 %4
  %scevgep41 = getelementptr i8, ptr %scevgep36, i64 -24
  %.1274 = load double, ptr %scevgep41, align 8
  %.1276 = fmul double %.1216, 2.000000e+00
  %.1277 = fadd double %.1187, %.1276
  %.1278 = fmul double %.1245, 2.000000e+00
  %.1279 = fadd double %.1277, %.1278
  %.1280 = fadd double %.1274, %.1279
  %.1281 = fmul double %.999, %.1280
  %.1282 = fadd double %.1160, %.1281
  %5 = shl i64 %lsr.iv, 3
  %scevgep30 = getelementptr i8, ptr %scevgep, i64 %5
  %scevgep35 = getelementptr i8, ptr %scevgep30, i64 -24
  store double %.1282, ptr %scevgep35, align 8
  %scevgep64 = getelementptr i8, ptr %scevgep614, i64 %5
  %scevgep65 = getelementptr i8, ptr %scevgep64, i64 -16
  %.1160.1 = load double, ptr %scevgep65, align 8
  %6 = shl i64 %lsr.iv, 3
  %scevgep58 = getelementptr i8, ptr %scevgep54, i64 %6
  %scevgep59 = getelementptr i8, ptr %scevgep58, i64 -16
  %.1187.1 = load double, ptr %scevgep59, align 8
  %7 = shl i64 %lsr.iv, 3
  %scevgep51 = getelementptr i8, ptr %scevgep598, i64 %7
  %scevgep52 = getelementptr i8, ptr %scevgep51, i64 -16
  %.1216.1 = load double, ptr %scevgep52, align 8
  %8 = shl i64 %lsr.iv, 3
  %scevgep45 = getelementptr i8, ptr %scevgep590, i64 %8
  %scevgep46 = getelementptr i8, ptr %scevgep45, i64 -16
  %.1245.1 = load double, ptr %scevgep46, align 8
  %9 = shl i64 %lsr.iv, 3
  %scevgep39 = getelementptr i8, ptr %scevgep582, i64 %9
  %scevgep40 = getelementptr i8, ptr %scevgep39, i64 -16
  %.1274.1 = load double, ptr %scevgep40, align 8
  %.1276.1 = fmul double %.1216.1, 2.000000e+00
  %.1277.1 = fadd double %.1187.1, %.1276.1
  %.1278.1 = fmul double %.1245.1, 2.000000e+00
  %.1279.1 = fadd double %.1277.1, %.1278.1
  %.1280.1 = fadd double %.1274.1, %.1279.1
  %.1281.1 = fmul double %.999, %.1280.1
  %.1282.1 = fadd double %.1160.1, %.1281.1
  %10 = shl i64 %lsr.iv, 3
  %scevgep33 = getelementptr i8, ptr %scevgep, i64 %10
  %scevgep34 = getelementptr i8, ptr %scevgep33, i64 -16
  store double %.1282.1, ptr %scevgep34, align 8
  %scevgep62 = getelementptr i8, ptr %scevgep614, i64 %10
  %scevgep63 = getelementptr i8, ptr %scevgep62, i64 -8
  %.1160.2 = load double, ptr %scevgep63, align 8
  %11 = shl i64 %lsr.iv, 3
  %scevgep56 = getelementptr i8, ptr %scevgep54, i64 %11
  %scevgep57 = getelementptr i8, ptr %scevgep56, i64 -8
  %.1187.2 = load double, ptr %scevgep57, align 8
  %12 = shl i64 %lsr.iv, 3
  %scevgep49 = getelementptr i8, ptr %scevgep598, i64 %12
  %scevgep50 = getelementptr i8, ptr %scevgep49, i64 -8
  %.1216.2 = load double, ptr %scevgep50, align 8
  %13 = shl i64 %lsr.iv, 3
  %scevgep43 = getelementptr i8, ptr %scevgep590, i64 %13
  %scevgep44 = getelementptr i8, ptr %scevgep43, i64 -8
  %.1245.2 = load double, ptr %scevgep44, align 8
  %14 = shl i64 %lsr.iv, 3
  %scevgep37 = getelementptr i8, ptr %scevgep582, i64 %14
  %scevgep38 = getelementptr i8, ptr %scevgep37, i64 -8
  %.1274.2 = load double, ptr %scevgep38, align 8
  %.1276.2 = fmul double %.1216.2, 2.000000e+00
  %.1277.2 = fadd double %.1187.2, %.1276.2
  %.1278.2 = fmul double %.1245.2, 2.000000e+00
  %.1279.2 = fadd double %.1277.2, %.1278.2
  %.1280.2 = fadd double %.1274.2, %.1279.2
  %.1281.2 = fmul double %.999, %.1280.2
  %.1282.2 = fadd double %.1160.2, %.1281.2
  %15 = shl i64 %lsr.iv, 3
  %scevgep31 = getelementptr i8, ptr %scevgep, i64 %15
  %scevgep32 = getelementptr i8, ptr %scevgep31, i64 -8
  store double %.1282.2, ptr %scevgep32, align 8
  %.1160.3 = load double, ptr %scevgep618, align 8
  %.1187.3 = load double, ptr %scevgep55, align 8
  %.1216.3 = load double, ptr %scevgep48, align 8
  %.1245.3 = load double, ptr %scevgep42, align 8
  %.1274.3 = load double, ptr %scevgep36, align 8
  %.1276.3 = fmul double %.1216.3, 2.000000e+00
  %.1277.3 = fadd double %.1187.3, %.1276.3
  %.1278.3 = fmul double %.1245.3, 2.000000e+00
  %.1279.3 = fadd double %.1277.3, %.1278.3
  %.1280.3 = fadd double %.1274.3, %.1279.3
  %.1281.3 = fmul double %.999, %.1280.3
  %.1282.3 = fadd double %.1160.3, %.1281.3
  store double %.1282.3, ptr %scevgep30, align 8
  %lsr.iv.next = add i64 %lsr.iv, 4
  %exitcond690.not.3 = icmp eq i64 %385, %lsr.iv.next
  br i1 %exitcond690.not.3, label %B13409755, label %B13409681, !llvm.loop !23

common.ret:                                       ; preds = %B13409637.else.if.if, %B13409637.if.if.if, %B0.endif.endif.else.if.if, %B0.endif.endif.if.if.endif.if, %B0.endif.endif.if.if.if, %B0.endif.if, %B13409755
  %common.ret.op = phi i32 [ 0, %B13409755 ], [ %.899.lcssa, %B13409637.else.if.if ], [ 1, %B0.endif.if ], [ 1, %B0.endif.endif.if.if.if ], [ 1, %B0.endif.endif.if.if.endif.if ], [ %.341, %B0.endif.endif.else.if.if ], [ 1, %B13409637.if.if.if ]
  ret i32 %common.ret.op

B13409755:                                        ; preds = %B13409681, %B13409681.prol.loopexit, %vec.epilog.middle.block475, %middle.block456, %B13409639.endif
  store double %.925.0, ptr %retptr, align 8
  br label %common.ret

B0.endif.if:                                      ; preds = %B0
  store ptr @.const.picklebuf.dc3bba832c4c3758273d0db24b835691af3f316c, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B0.endif.endif:                                   ; preds = %B0
  %sunkaddr836 = getelementptr inbounds i8, ptr %.90, i64 32
  %.172 = load ptr, ptr %sunkaddr836, align 8
  %.268.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.K.0, 0
  %.268.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.0.insert, ptr %arg.K.1, 1
  %.268.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.1.insert, i64 %arg.K.5.1, 2
  %.268.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.2.insert, i64 %arg.K.3, 3
  %.268.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %arg.K.4, 4
  %.268.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.4.insert, i64 %arg.K.5.1, 5, 0
  %.268.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.5.0.insert, i64 %arg.K.6.1, 6, 0
  %.270.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.par.0, 0
  %.270.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.0.insert, ptr %arg.par.1, 1
  %.270.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.1.insert, i64 %arg.par.2, 2
  %.270.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.2.insert, i64 %arg.par.3, 3
  %.270.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.3.insert, ptr %arg.par.4, 4
  %.270.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.4.insert, i64 %arg.par.5.0, 5, 0
  %.270.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.5.0.insert, i64 %arg.par.6.0, 6, 0
  %.280 = icmp eq ptr %arg.f.2, null
  br i1 %.280, label %B0.endif.endif.if, label %B0.endif.endif.else, !prof !0

B0.endif.endif.if:                                ; preds = %B0.endif.endif
  %.284 = icmp eq ptr %arg.f.0, null
  br i1 %.284, label %B0.endif.endif.if.if, label %B0.endif.endif.if.endif, !prof !0

B0.endif.endif.else:                              ; preds = %B0.endif.endif
  store double 0.000000e+00, ptr %.331, align 8
  %.341 = call i32 %arg.f.2(ptr nonnull %.331, ptr nonnull %excinfo.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.1, i64 %arg.K.6.1)
  %.351 = load double, ptr %.331, align 8
  switch i32 %.341, label %B0.endif.endif.else.if.if [
    i32 -2, label %B0.endif.endif.endif.endif.endif
    i32 0, label %B0.endif.endif.endif.endif.endif
  ], !prof !4

B0.endif.endif.if.if:                             ; preds = %B0.endif.endif.if
  %.286 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers2rk8rk4_stepB3v74B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMVC_2fAwA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE, align 8
  %.287 = icmp eq ptr %.286, null
  br i1 %.287, label %B0.endif.endif.if.if.if, label %B0.endif.endif.if.if.endif, !prof !0

B0.endif.endif.if.endif:                          ; preds = %B0.endif.endif.if.if.endif.endif, %B0.endif.endif.if
  %fptr_of_f.0 = phi ptr [ %.317, %B0.endif.endif.if.if.endif.endif ], [ %arg.f.0, %B0.endif.endif.if ]
  %.327 = call double %fptr_of_f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.71.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.6.0.insert)
  br label %B0.endif.endif.endif.endif.endif

B0.endif.endif.if.if.if:                          ; preds = %B0.endif.endif.if.if
  store ptr @.const.picklebuf.f52a4d7919abe2cf3e7519de076bcff016108bed, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B0.endif.endif.if.if.endif:                       ; preds = %B0.endif.endif.if.if
  call void @numba_gil_ensure(ptr nonnull %.296)
  %.299 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.17)
  %.300 = call ptr @PyObject_GetAttrString(ptr %.299, ptr nonnull @.const._get_wrapper_address.18)
  call void @Py_DecRef(ptr %.299)
  %.308 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.19, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.20)
  %.309 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.300, ptr %arg.f.1, ptr %.308, ptr null)
  %.310 = icmp eq ptr %.309, null
  br i1 %.310, label %B0.endif.endif.if.if.endif.if, label %B0.endif.endif.if.if.endif.endif, !prof !0

B0.endif.endif.if.if.endif.if:                    ; preds = %B0.endif.endif.if.if.endif
  store ptr @.const.picklebuf.32c8b183712bee87dcda2e43a3f74916a0d4de74, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B0.endif.endif.if.if.endif.endif:                 ; preds = %B0.endif.endif.if.if.endif
  %.317 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.309)
  call void @Py_DecRef(ptr nonnull %.309)
  call void @numba_gil_release(ptr nonnull %.296)
  br label %B0.endif.endif.if.endif

B0.endif.endif.else.if.if:                        ; preds = %B0.endif.endif.else
  %.349 = icmp sgt i32 %.341, 0
  %.342 = load ptr, ptr %excinfo.2, align 8
  %.350 = select i1 %.349, ptr %.342, ptr undef
  store ptr %.350, ptr %excinfo, align 8
  br label %common.ret

B0.endif.endif.endif.endif.endif:                 ; preds = %B0.endif.endif.if.endif, %B0.endif.endif.else, %B0.endif.endif.else
  %.278.0 = phi double [ %.327, %B0.endif.endif.if.endif ], [ %.351, %B0.endif.endif.else ], [ %.351, %B0.endif.endif.else ]
  %16 = icmp eq ptr %arg.f.2, null
  %.543.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ytmp.0, 0
  %.543.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.0.insert, ptr %arg.ytmp.1, 1
  %.543.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.1.insert, i64 %arg.ytmp.2, 2
  %.543.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.2.insert, i64 %arg.ytmp.3, 3
  %.543.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.3.insert, ptr %arg.ytmp.4, 4
  %.543.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.4.insert, i64 %arg.ytmp.5.0, 5, 0
  %.543.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.5.0.insert, i64 %arg.ytmp.6.0, 6, 0
  %.524.us.us = fmul double %arg.h, 5.000000e-01
  br i1 %16, label %B0.endif.endif.endif.endif.endif.split.us, label %B178.preheader, !prof !0

B178.preheader:                                   ; preds = %B0.endif.endif.endif.endif.endif
  %17 = icmp slt i64 %arg.y.2, 1
  br i1 %17, label %B13409637, label %iter.check

iter.check:                                       ; preds = %B178.preheader
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check, label %B13409633.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %iter.check
  %18 = ptrtoint ptr %.172 to i64
  %19 = ptrtoint ptr %arg.ytmp.4 to i64
  %20 = ptrtoint ptr %arg.y.4 to i64
  %21 = sub i64 %19, %20
  %diff.check = icmp ult i64 %21, 256
  %22 = sub i64 %19, %18
  %diff.check25 = icmp ult i64 %22, 256
  %conflict.rdx = or i1 %diff.check, %diff.check25
  br i1 %conflict.rdx, label %B13409633.preheader, label %vector.main.loop.iter.check

vector.main.loop.iter.check:                      ; preds = %vector.memcheck
  %const = bitcast i64 9223372036854775776 to i64
  %min.iters.check26 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check26, label %vec.epilog.ph, label %vector.ph

vector.ph:                                        ; preds = %vector.main.loop.iter.check
  %n.vec = and i64 %arg.y.2, %const
  %broadcast.splatinsert = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %sunkaddr837 = mul i64 %index, 8
  %sunkaddr838 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr837
  %wide.load = load <8 x double>, ptr %sunkaddr838, align 8
  %sunkaddr839 = mul i64 %index, 8
  %sunkaddr840 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr839
  %sunkaddr841 = getelementptr i8, ptr %sunkaddr840, i64 64
  %wide.load27 = load <8 x double>, ptr %sunkaddr841, align 8
  %sunkaddr842 = mul i64 %index, 8
  %sunkaddr843 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr842
  %sunkaddr844 = getelementptr i8, ptr %sunkaddr843, i64 128
  %wide.load28 = load <8 x double>, ptr %sunkaddr844, align 8
  %sunkaddr845 = mul i64 %index, 8
  %sunkaddr846 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr845
  %sunkaddr847 = getelementptr i8, ptr %sunkaddr846, i64 192
  %wide.load29 = load <8 x double>, ptr %sunkaddr847, align 8
  %sunkaddr848 = mul i64 %index, 8
  %sunkaddr849 = getelementptr i8, ptr %.172, i64 %sunkaddr848
  %wide.load30 = load <8 x double>, ptr %sunkaddr849, align 8
  %sunkaddr850 = mul i64 %index, 8
  %sunkaddr851 = getelementptr i8, ptr %.172, i64 %sunkaddr850
  %sunkaddr852 = getelementptr i8, ptr %sunkaddr851, i64 64
  %wide.load31 = load <8 x double>, ptr %sunkaddr852, align 8
  %sunkaddr853 = mul i64 %index, 8
  %sunkaddr854 = getelementptr i8, ptr %.172, i64 %sunkaddr853
  %sunkaddr855 = getelementptr i8, ptr %sunkaddr854, i64 128
  %wide.load32 = load <8 x double>, ptr %sunkaddr855, align 8
  %sunkaddr856 = mul i64 %index, 8
  %sunkaddr857 = getelementptr i8, ptr %.172, i64 %sunkaddr856
  %sunkaddr858 = getelementptr i8, ptr %sunkaddr857, i64 192
  %wide.load33 = load <8 x double>, ptr %sunkaddr858, align 8
  %23 = fmul <8 x double> %broadcast.splat, %wide.load30
  %24 = fmul <8 x double> %broadcast.splat, %wide.load31
  %25 = fmul <8 x double> %broadcast.splat, %wide.load32
  %26 = fmul <8 x double> %broadcast.splat, %wide.load33
  %27 = fadd <8 x double> %wide.load, %23
  %28 = fadd <8 x double> %wide.load27, %24
  %29 = fadd <8 x double> %wide.load28, %25
  %30 = fadd <8 x double> %wide.load29, %26
  %sunkaddr859 = mul i64 %index, 8
  %sunkaddr860 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr859
  store <8 x double> %27, ptr %sunkaddr860, align 8
  %sunkaddr861 = mul i64 %index, 8
  %sunkaddr862 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr861
  %sunkaddr863 = getelementptr i8, ptr %sunkaddr862, i64 64
  store <8 x double> %28, ptr %sunkaddr863, align 8
  %sunkaddr864 = mul i64 %index, 8
  %sunkaddr865 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr864
  %sunkaddr866 = getelementptr i8, ptr %sunkaddr865, i64 128
  store <8 x double> %29, ptr %sunkaddr866, align 8
  %sunkaddr867 = mul i64 %index, 8
  %sunkaddr868 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr867
  %sunkaddr869 = getelementptr i8, ptr %sunkaddr868, i64 192
  store <8 x double> %30, ptr %sunkaddr869, align 8
  %index.next = add nuw nsw i64 %index, 32
  %31 = icmp eq i64 %n.vec, %index.next
  br i1 %31, label %middle.block, label %vector.body, !llvm.loop !24

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B13409637, label %vec.epilog.iter.check

vec.epilog.iter.check:                            ; preds = %middle.block
  %32 = and i64 %arg.y.2, 28
  %min.epilog.iters.check = icmp eq i64 %32, 0
  br i1 %min.epilog.iters.check, label %B13409633.preheader, label %vec.epilog.ph, !prof !9

vec.epilog.ph:                                    ; preds = %vec.epilog.iter.check, %vector.main.loop.iter.check
  %vec.epilog.resume.val = phi i64 [ %n.vec, %vec.epilog.iter.check ], [ 0, %vector.main.loop.iter.check ]
  %const_mat = add i64 %const, 28
  %n.vec35 = and i64 %arg.y.2, %const_mat
  %broadcast.splatinsert36 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat37 = shufflevector <4 x double> %broadcast.splatinsert36, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body

vec.epilog.vector.body:                           ; preds = %vec.epilog.vector.body, %vec.epilog.ph
  %index38 = phi i64 [ %vec.epilog.resume.val, %vec.epilog.ph ], [ %index.next41, %vec.epilog.vector.body ]
  %33 = shl i64 %index38, 3
  %scevgep1367 = getelementptr i8, ptr %arg.y.4, i64 %33
  %wide.load39 = load <4 x double>, ptr %scevgep1367, align 8
  %scevgep1366 = getelementptr i8, ptr %.172, i64 %33
  %wide.load40 = load <4 x double>, ptr %scevgep1366, align 8
  %34 = fmul <4 x double> %broadcast.splat37, %wide.load40
  %35 = fadd <4 x double> %wide.load39, %34
  %36 = shl i64 %index38, 3
  %scevgep720 = getelementptr i8, ptr %arg.ytmp.4, i64 %36
  store <4 x double> %35, ptr %scevgep720, align 8
  %index.next41 = add nuw i64 %index38, 4
  %37 = icmp eq i64 %n.vec35, %index.next41
  br i1 %37, label %vec.epilog.middle.block, label %vec.epilog.vector.body, !llvm.loop !25

vec.epilog.middle.block:                          ; preds = %vec.epilog.vector.body
  %cmp.n42 = icmp eq i64 %arg.y.2, %n.vec35
  br i1 %cmp.n42, label %B13409637, label %B13409633.preheader

B13409633.preheader:                              ; preds = %vec.epilog.middle.block, %vec.epilog.iter.check, %vector.memcheck, %iter.check
  %.632619621.ph = phi i64 [ 0, %iter.check ], [ 0, %vector.memcheck ], [ %n.vec, %vec.epilog.iter.check ], [ %n.vec35, %vec.epilog.middle.block ]
  %38 = sub nsw i64 %arg.y.2, %.632619621.ph
  %xtraiter = and i64 %38, 7
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B13409633.prol.loopexit, label %B13409633.prol.preheader

B13409633.prol.preheader:                         ; preds = %B13409633.preheader
  br label %B13409633.prol

B13409633.prol:                                   ; preds = %B13409633.prol.preheader, %B13409633.prol
  %lsr.iv1363 = phi i64 [ %lsr.iv.next1364, %B13409633.prol ], [ %xtraiter, %B13409633.prol.preheader ]
  %.632619621.prol = phi i64 [ %.639.prol, %B13409633.prol ], [ %.632619621.ph, %B13409633.prol.preheader ]
  %.639.prol = add nuw i64 %.632619621.prol, 1
  %39 = shl i64 %.632619621.prol, 3
  %scevgep1362 = getelementptr i8, ptr %arg.y.4, i64 %39
  %.691.prol = load double, ptr %scevgep1362, align 8
  %scevgep1361 = getelementptr i8, ptr %.172, i64 %39
  %.720.prol = load double, ptr %scevgep1361, align 8
  %.722.prol = fmul double %.524.us.us, %.720.prol
  %.723.prol = fadd double %.691.prol, %.722.prol
  %40 = shl i64 %.632619621.prol, 3
  %scevgep719 = getelementptr i8, ptr %arg.ytmp.4, i64 %40
  store double %.723.prol, ptr %scevgep719, align 8
  %lsr.iv.next1364 = add nsw i64 %lsr.iv1363, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next1364, 0
  br i1 %prol.iter.cmp.not, label %B13409633.prol.loopexit, label %B13409633.prol, !llvm.loop !26

B13409633.prol.loopexit:                          ; preds = %B13409633.prol, %B13409633.preheader
  %.632619621.unr = phi i64 [ %.632619621.ph, %B13409633.preheader ], [ %.639.prol, %B13409633.prol ]
  %41 = sub nsw i64 %.632619621.ph, %arg.y.2
  %42 = icmp ugt i64 %41, -8
  br i1 %42, label %B13409637, label %B13409633.preheader29

B13409633.preheader29:                            ; preds = %B13409633.prol.loopexit
  br label %B13409633

B0.endif.endif.endif.endif.endif.split.us:        ; preds = %B0.endif.endif.endif.endif.endif
  %.852 = icmp eq ptr %arg.f.0, null
  br i1 %.852, label %B178.us.us.preheader, label %B178.us.preheader, !prof !0

B178.us.preheader:                                ; preds = %B0.endif.endif.endif.endif.endif.split.us
  %43 = icmp slt i64 %arg.y.2, 1
  br i1 %43, label %B13409637.endif.endif.us, label %iter.check143

iter.check143:                                    ; preds = %B178.us.preheader
  %min.iters.check141 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check141, label %B13409633.us.preheader, label %vector.memcheck135

vector.memcheck135:                               ; preds = %iter.check143
  %44 = ptrtoint ptr %.172 to i64
  %45 = ptrtoint ptr %arg.ytmp.4 to i64
  %46 = ptrtoint ptr %arg.y.4 to i64
  %47 = sub i64 %45, %46
  %diff.check138 = icmp ult i64 %47, 256
  %48 = sub i64 %45, %44
  %diff.check139 = icmp ult i64 %48, 256
  %conflict.rdx140 = or i1 %diff.check138, %diff.check139
  br i1 %conflict.rdx140, label %B13409633.us.preheader, label %vector.main.loop.iter.check145

vector.main.loop.iter.check145:                   ; preds = %vector.memcheck135
  %const756 = bitcast i64 9223372036854775776 to i64
  %min.iters.check144 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check144, label %vec.epilog.ph168, label %vector.ph146

vector.ph146:                                     ; preds = %vector.main.loop.iter.check145
  %n.vec148 = and i64 %arg.y.2, %const756
  %broadcast.splatinsert149 = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat150 = shufflevector <8 x double> %broadcast.splatinsert149, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body151

vector.body151:                                   ; preds = %vector.body151, %vector.ph146
  %index152 = phi i64 [ 0, %vector.ph146 ], [ %index.next161, %vector.body151 ]
  %sunkaddr870 = mul i64 %index152, 8
  %sunkaddr871 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr870
  %wide.load153 = load <8 x double>, ptr %sunkaddr871, align 8
  %sunkaddr872 = mul i64 %index152, 8
  %sunkaddr873 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr872
  %sunkaddr874 = getelementptr i8, ptr %sunkaddr873, i64 64
  %wide.load154 = load <8 x double>, ptr %sunkaddr874, align 8
  %sunkaddr875 = mul i64 %index152, 8
  %sunkaddr876 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr875
  %sunkaddr877 = getelementptr i8, ptr %sunkaddr876, i64 128
  %wide.load155 = load <8 x double>, ptr %sunkaddr877, align 8
  %sunkaddr878 = mul i64 %index152, 8
  %sunkaddr879 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr878
  %sunkaddr880 = getelementptr i8, ptr %sunkaddr879, i64 192
  %wide.load156 = load <8 x double>, ptr %sunkaddr880, align 8
  %sunkaddr881 = mul i64 %index152, 8
  %sunkaddr882 = getelementptr i8, ptr %.172, i64 %sunkaddr881
  %wide.load157 = load <8 x double>, ptr %sunkaddr882, align 8
  %sunkaddr883 = mul i64 %index152, 8
  %sunkaddr884 = getelementptr i8, ptr %.172, i64 %sunkaddr883
  %sunkaddr885 = getelementptr i8, ptr %sunkaddr884, i64 64
  %wide.load158 = load <8 x double>, ptr %sunkaddr885, align 8
  %sunkaddr886 = mul i64 %index152, 8
  %sunkaddr887 = getelementptr i8, ptr %.172, i64 %sunkaddr886
  %sunkaddr888 = getelementptr i8, ptr %sunkaddr887, i64 128
  %wide.load159 = load <8 x double>, ptr %sunkaddr888, align 8
  %sunkaddr889 = mul i64 %index152, 8
  %sunkaddr890 = getelementptr i8, ptr %.172, i64 %sunkaddr889
  %sunkaddr891 = getelementptr i8, ptr %sunkaddr890, i64 192
  %wide.load160 = load <8 x double>, ptr %sunkaddr891, align 8
  %49 = fmul <8 x double> %broadcast.splat150, %wide.load157
  %50 = fmul <8 x double> %broadcast.splat150, %wide.load158
  %51 = fmul <8 x double> %broadcast.splat150, %wide.load159
  %52 = fmul <8 x double> %broadcast.splat150, %wide.load160
  %53 = fadd <8 x double> %wide.load153, %49
  %54 = fadd <8 x double> %wide.load154, %50
  %55 = fadd <8 x double> %wide.load155, %51
  %56 = fadd <8 x double> %wide.load156, %52
  %sunkaddr892 = mul i64 %index152, 8
  %sunkaddr893 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr892
  store <8 x double> %53, ptr %sunkaddr893, align 8
  %sunkaddr894 = mul i64 %index152, 8
  %sunkaddr895 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr894
  %sunkaddr896 = getelementptr i8, ptr %sunkaddr895, i64 64
  store <8 x double> %54, ptr %sunkaddr896, align 8
  %sunkaddr897 = mul i64 %index152, 8
  %sunkaddr898 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr897
  %sunkaddr899 = getelementptr i8, ptr %sunkaddr898, i64 128
  store <8 x double> %55, ptr %sunkaddr899, align 8
  %sunkaddr900 = mul i64 %index152, 8
  %sunkaddr901 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr900
  %sunkaddr902 = getelementptr i8, ptr %sunkaddr901, i64 192
  store <8 x double> %56, ptr %sunkaddr902, align 8
  %index.next161 = add nuw nsw i64 %index152, 32
  %57 = icmp eq i64 %n.vec148, %index.next161
  br i1 %57, label %middle.block162, label %vector.body151, !llvm.loop !27

middle.block162:                                  ; preds = %vector.body151
  %cmp.n163 = icmp eq i64 %arg.y.2, %n.vec148
  br i1 %cmp.n163, label %B13409637.endif.endif.us, label %vec.epilog.iter.check166

vec.epilog.iter.check166:                         ; preds = %middle.block162
  %58 = and i64 %arg.y.2, 28
  %min.epilog.iters.check167 = icmp eq i64 %58, 0
  br i1 %min.epilog.iters.check167, label %B13409633.us.preheader, label %vec.epilog.ph168, !prof !9

vec.epilog.ph168:                                 ; preds = %vec.epilog.iter.check166, %vector.main.loop.iter.check145
  %vec.epilog.resume.val164 = phi i64 [ %n.vec148, %vec.epilog.iter.check166 ], [ 0, %vector.main.loop.iter.check145 ]
  %const_mat757 = add i64 %const756, 28
  %n.vec170 = and i64 %arg.y.2, %const_mat757
  %broadcast.splatinsert171 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat172 = shufflevector <4 x double> %broadcast.splatinsert171, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body173

vec.epilog.vector.body173:                        ; preds = %vec.epilog.vector.body173, %vec.epilog.ph168
  %index174 = phi i64 [ %vec.epilog.resume.val164, %vec.epilog.ph168 ], [ %index.next177, %vec.epilog.vector.body173 ]
  %59 = shl i64 %index174, 3
  %scevgep1127 = getelementptr i8, ptr %arg.y.4, i64 %59
  %wide.load175 = load <4 x double>, ptr %scevgep1127, align 8
  %scevgep1126 = getelementptr i8, ptr %.172, i64 %59
  %wide.load176 = load <4 x double>, ptr %scevgep1126, align 8
  %60 = fmul <4 x double> %broadcast.splat172, %wide.load176
  %61 = fadd <4 x double> %wide.load175, %60
  %62 = shl i64 %index174, 3
  %scevgep496 = getelementptr i8, ptr %arg.ytmp.4, i64 %62
  store <4 x double> %61, ptr %scevgep496, align 8
  %index.next177 = add nuw i64 %index174, 4
  %63 = icmp eq i64 %n.vec170, %index.next177
  br i1 %63, label %vec.epilog.middle.block178, label %vec.epilog.vector.body173, !llvm.loop !28

vec.epilog.middle.block178:                       ; preds = %vec.epilog.vector.body173
  %cmp.n179 = icmp eq i64 %arg.y.2, %n.vec170
  br i1 %cmp.n179, label %B13409637.endif.endif.us, label %B13409633.us.preheader

B13409633.us.preheader:                           ; preds = %vec.epilog.middle.block178, %vec.epilog.iter.check166, %vector.memcheck135, %iter.check143
  %.632619621.us.ph = phi i64 [ 0, %iter.check143 ], [ 0, %vector.memcheck135 ], [ %n.vec148, %vec.epilog.iter.check166 ], [ %n.vec170, %vec.epilog.middle.block178 ]
  %64 = sub nsw i64 %arg.y.2, %.632619621.us.ph
  %xtraiter504 = and i64 %64, 7
  %lcmp.mod505.not = icmp eq i64 %xtraiter504, 0
  br i1 %lcmp.mod505.not, label %B13409633.us.prol.loopexit, label %B13409633.us.prol.preheader

B13409633.us.prol.preheader:                      ; preds = %B13409633.us.preheader
  br label %B13409633.us.prol

B13409633.us.prol:                                ; preds = %B13409633.us.prol.preheader, %B13409633.us.prol
  %lsr.iv1123 = phi i64 [ %lsr.iv.next1124, %B13409633.us.prol ], [ %xtraiter504, %B13409633.us.prol.preheader ]
  %.632619621.us.prol = phi i64 [ %.639.us.prol, %B13409633.us.prol ], [ %.632619621.us.ph, %B13409633.us.prol.preheader ]
  %.639.us.prol = add nuw i64 %.632619621.us.prol, 1
  %65 = shl i64 %.632619621.us.prol, 3
  %scevgep1122 = getelementptr i8, ptr %arg.y.4, i64 %65
  %.691.us.prol = load double, ptr %scevgep1122, align 8
  %scevgep1121 = getelementptr i8, ptr %.172, i64 %65
  %.720.us.prol = load double, ptr %scevgep1121, align 8
  %.722.us.prol = fmul double %.524.us.us, %.720.us.prol
  %.723.us.prol = fadd double %.691.us.prol, %.722.us.prol
  %66 = shl i64 %.632619621.us.prol, 3
  %scevgep495 = getelementptr i8, ptr %arg.ytmp.4, i64 %66
  store double %.723.us.prol, ptr %scevgep495, align 8
  %lsr.iv.next1124 = add nsw i64 %lsr.iv1123, -1
  %prol.iter506.cmp.not = icmp eq i64 %lsr.iv.next1124, 0
  br i1 %prol.iter506.cmp.not, label %B13409633.us.prol.loopexit, label %B13409633.us.prol, !llvm.loop !29

B13409633.us.prol.loopexit:                       ; preds = %B13409633.us.prol, %B13409633.us.preheader
  %.632619621.us.unr = phi i64 [ %.632619621.us.ph, %B13409633.us.preheader ], [ %.639.us.prol, %B13409633.us.prol ]
  %67 = sub nsw i64 %.632619621.us.ph, %arg.y.2
  %68 = icmp ugt i64 %67, -8
  br i1 %68, label %B13409637.endif.endif.us, label %B13409633.us.preheader28

B13409633.us.preheader28:                         ; preds = %B13409633.us.prol.loopexit
  br label %B13409633.us

B178.us.us.preheader:                             ; preds = %B0.endif.endif.endif.endif.endif.split.us
  %69 = icmp slt i64 %arg.y.2, 1
  br i1 %69, label %B13409637.us.us, label %iter.check281

iter.check281:                                    ; preds = %B178.us.us.preheader
  %min.iters.check279 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check279, label %B13409633.us.us.preheader, label %vector.memcheck273

vector.memcheck273:                               ; preds = %iter.check281
  %70 = ptrtoint ptr %.172 to i64
  %71 = ptrtoint ptr %arg.ytmp.4 to i64
  %72 = ptrtoint ptr %arg.y.4 to i64
  %73 = sub i64 %71, %72
  %diff.check276 = icmp ult i64 %73, 256
  %74 = sub i64 %71, %70
  %diff.check277 = icmp ult i64 %74, 256
  %conflict.rdx278 = or i1 %diff.check276, %diff.check277
  br i1 %conflict.rdx278, label %B13409633.us.us.preheader, label %vector.main.loop.iter.check283

vector.main.loop.iter.check283:                   ; preds = %vector.memcheck273
  %const762 = bitcast i64 9223372036854775776 to i64
  %min.iters.check282 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check282, label %vec.epilog.ph306, label %vector.ph284

vector.ph284:                                     ; preds = %vector.main.loop.iter.check283
  %n.vec286 = and i64 %arg.y.2, %const762
  %broadcast.splatinsert287 = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat288 = shufflevector <8 x double> %broadcast.splatinsert287, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body289

vector.body289:                                   ; preds = %vector.body289, %vector.ph284
  %index290 = phi i64 [ 0, %vector.ph284 ], [ %index.next299, %vector.body289 ]
  %sunkaddr903 = mul i64 %index290, 8
  %sunkaddr904 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr903
  %wide.load291 = load <8 x double>, ptr %sunkaddr904, align 8
  %sunkaddr905 = mul i64 %index290, 8
  %sunkaddr906 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr905
  %sunkaddr907 = getelementptr i8, ptr %sunkaddr906, i64 64
  %wide.load292 = load <8 x double>, ptr %sunkaddr907, align 8
  %sunkaddr908 = mul i64 %index290, 8
  %sunkaddr909 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr908
  %sunkaddr910 = getelementptr i8, ptr %sunkaddr909, i64 128
  %wide.load293 = load <8 x double>, ptr %sunkaddr910, align 8
  %sunkaddr911 = mul i64 %index290, 8
  %sunkaddr912 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr911
  %sunkaddr913 = getelementptr i8, ptr %sunkaddr912, i64 192
  %wide.load294 = load <8 x double>, ptr %sunkaddr913, align 8
  %sunkaddr914 = mul i64 %index290, 8
  %sunkaddr915 = getelementptr i8, ptr %.172, i64 %sunkaddr914
  %wide.load295 = load <8 x double>, ptr %sunkaddr915, align 8
  %sunkaddr916 = mul i64 %index290, 8
  %sunkaddr917 = getelementptr i8, ptr %.172, i64 %sunkaddr916
  %sunkaddr918 = getelementptr i8, ptr %sunkaddr917, i64 64
  %wide.load296 = load <8 x double>, ptr %sunkaddr918, align 8
  %sunkaddr919 = mul i64 %index290, 8
  %sunkaddr920 = getelementptr i8, ptr %.172, i64 %sunkaddr919
  %sunkaddr921 = getelementptr i8, ptr %sunkaddr920, i64 128
  %wide.load297 = load <8 x double>, ptr %sunkaddr921, align 8
  %sunkaddr922 = mul i64 %index290, 8
  %sunkaddr923 = getelementptr i8, ptr %.172, i64 %sunkaddr922
  %sunkaddr924 = getelementptr i8, ptr %sunkaddr923, i64 192
  %wide.load298 = load <8 x double>, ptr %sunkaddr924, align 8
  %75 = fmul <8 x double> %broadcast.splat288, %wide.load295
  %76 = fmul <8 x double> %broadcast.splat288, %wide.load296
  %77 = fmul <8 x double> %broadcast.splat288, %wide.load297
  %78 = fmul <8 x double> %broadcast.splat288, %wide.load298
  %79 = fadd <8 x double> %wide.load291, %75
  %80 = fadd <8 x double> %wide.load292, %76
  %81 = fadd <8 x double> %wide.load293, %77
  %82 = fadd <8 x double> %wide.load294, %78
  %sunkaddr925 = mul i64 %index290, 8
  %sunkaddr926 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr925
  store <8 x double> %79, ptr %sunkaddr926, align 8
  %sunkaddr927 = mul i64 %index290, 8
  %sunkaddr928 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr927
  %sunkaddr929 = getelementptr i8, ptr %sunkaddr928, i64 64
  store <8 x double> %80, ptr %sunkaddr929, align 8
  %sunkaddr930 = mul i64 %index290, 8
  %sunkaddr931 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr930
  %sunkaddr932 = getelementptr i8, ptr %sunkaddr931, i64 128
  store <8 x double> %81, ptr %sunkaddr932, align 8
  %sunkaddr933 = mul i64 %index290, 8
  %sunkaddr934 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr933
  %sunkaddr935 = getelementptr i8, ptr %sunkaddr934, i64 192
  store <8 x double> %82, ptr %sunkaddr935, align 8
  %index.next299 = add nuw nsw i64 %index290, 32
  %83 = icmp eq i64 %n.vec286, %index.next299
  br i1 %83, label %middle.block300, label %vector.body289, !llvm.loop !30

middle.block300:                                  ; preds = %vector.body289
  %cmp.n301 = icmp eq i64 %arg.y.2, %n.vec286
  br i1 %cmp.n301, label %B13409637.us.us, label %vec.epilog.iter.check304

vec.epilog.iter.check304:                         ; preds = %middle.block300
  %84 = and i64 %arg.y.2, 28
  %min.epilog.iters.check305 = icmp eq i64 %84, 0
  br i1 %min.epilog.iters.check305, label %B13409633.us.us.preheader, label %vec.epilog.ph306, !prof !9

vec.epilog.ph306:                                 ; preds = %vec.epilog.iter.check304, %vector.main.loop.iter.check283
  %vec.epilog.resume.val302 = phi i64 [ %n.vec286, %vec.epilog.iter.check304 ], [ 0, %vector.main.loop.iter.check283 ]
  %const_mat763 = add i64 %const762, 28
  %n.vec308 = and i64 %arg.y.2, %const_mat763
  %broadcast.splatinsert309 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat310 = shufflevector <4 x double> %broadcast.splatinsert309, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body311

vec.epilog.vector.body311:                        ; preds = %vec.epilog.vector.body311, %vec.epilog.ph306
  %index312 = phi i64 [ %vec.epilog.resume.val302, %vec.epilog.ph306 ], [ %index.next315, %vec.epilog.vector.body311 ]
  %85 = shl i64 %index312, 3
  %scevgep887 = getelementptr i8, ptr %arg.y.4, i64 %85
  %wide.load313 = load <4 x double>, ptr %scevgep887, align 8
  %scevgep886 = getelementptr i8, ptr %.172, i64 %85
  %wide.load314 = load <4 x double>, ptr %scevgep886, align 8
  %86 = fmul <4 x double> %broadcast.splat310, %wide.load314
  %87 = fadd <4 x double> %wide.load313, %86
  %88 = shl i64 %index312, 3
  %scevgep290 = getelementptr i8, ptr %arg.ytmp.4, i64 %88
  store <4 x double> %87, ptr %scevgep290, align 8
  %index.next315 = add nuw i64 %index312, 4
  %89 = icmp eq i64 %n.vec308, %index.next315
  br i1 %89, label %vec.epilog.middle.block316, label %vec.epilog.vector.body311, !llvm.loop !31

vec.epilog.middle.block316:                       ; preds = %vec.epilog.vector.body311
  %cmp.n317 = icmp eq i64 %arg.y.2, %n.vec308
  br i1 %cmp.n317, label %B13409637.us.us, label %B13409633.us.us.preheader

B13409633.us.us.preheader:                        ; preds = %vec.epilog.middle.block316, %vec.epilog.iter.check304, %vector.memcheck273, %iter.check281
  %.632619621.us.us.ph = phi i64 [ 0, %iter.check281 ], [ 0, %vector.memcheck273 ], [ %n.vec286, %vec.epilog.iter.check304 ], [ %n.vec308, %vec.epilog.middle.block316 ]
  %90 = sub nsw i64 %arg.y.2, %.632619621.us.us.ph
  %xtraiter533 = and i64 %90, 7
  %lcmp.mod534.not = icmp eq i64 %xtraiter533, 0
  br i1 %lcmp.mod534.not, label %B13409633.us.us.prol.loopexit, label %B13409633.us.us.prol.preheader

B13409633.us.us.prol.preheader:                   ; preds = %B13409633.us.us.preheader
  br label %B13409633.us.us.prol

B13409633.us.us.prol:                             ; preds = %B13409633.us.us.prol.preheader, %B13409633.us.us.prol
  %lsr.iv883 = phi i64 [ %lsr.iv.next884, %B13409633.us.us.prol ], [ %xtraiter533, %B13409633.us.us.prol.preheader ]
  %.632619621.us.us.prol = phi i64 [ %.639.us.us.prol, %B13409633.us.us.prol ], [ %.632619621.us.us.ph, %B13409633.us.us.prol.preheader ]
  %.639.us.us.prol = add nuw i64 %.632619621.us.us.prol, 1
  %91 = shl i64 %.632619621.us.us.prol, 3
  %scevgep882 = getelementptr i8, ptr %arg.y.4, i64 %91
  %.691.us.us.prol = load double, ptr %scevgep882, align 8
  %scevgep881 = getelementptr i8, ptr %.172, i64 %91
  %.720.us.us.prol = load double, ptr %scevgep881, align 8
  %.722.us.us.prol = fmul double %.524.us.us, %.720.us.us.prol
  %.723.us.us.prol = fadd double %.691.us.us.prol, %.722.us.us.prol
  %92 = shl i64 %.632619621.us.us.prol, 3
  %scevgep289 = getelementptr i8, ptr %arg.ytmp.4, i64 %92
  store double %.723.us.us.prol, ptr %scevgep289, align 8
  %lsr.iv.next884 = add nsw i64 %lsr.iv883, -1
  %prol.iter535.cmp.not = icmp eq i64 %lsr.iv.next884, 0
  br i1 %prol.iter535.cmp.not, label %B13409633.us.us.prol.loopexit, label %B13409633.us.us.prol, !llvm.loop !32

B13409633.us.us.prol.loopexit:                    ; preds = %B13409633.us.us.prol, %B13409633.us.us.preheader
  %.632619621.us.us.unr = phi i64 [ %.632619621.us.us.ph, %B13409633.us.us.preheader ], [ %.639.us.us.prol, %B13409633.us.us.prol ]
  %93 = sub nsw i64 %.632619621.us.us.ph, %arg.y.2
  %94 = icmp ugt i64 %93, -8
  br i1 %94, label %B13409637.us.us, label %B13409633.us.us.preheader27

B13409633.us.us.preheader27:                      ; preds = %B13409633.us.us.prol.loopexit
  br label %B13409633.us.us

B13409637.us.us:                                  ; preds = %B13409633.us.us, %B13409633.us.us.prol.loopexit, %vec.epilog.middle.block316, %middle.block300, %B178.us.us.preheader
  call void @numba_gil_ensure(ptr nonnull %.854)
  %.857.us.us = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.17)
  %.858.us.us = call ptr @PyObject_GetAttrString(ptr %.857.us.us, ptr nonnull @.const._get_wrapper_address.18)
  call void @Py_DecRef(ptr %.857.us.us)
  %.866.us.us = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.19, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.20)
  %.867.us.us = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.858.us.us, ptr %arg.f.1, ptr %.866.us.us, ptr null)
  %.868.us.us = icmp eq ptr %.867.us.us, null
  br i1 %.868.us.us, label %B13409637.if.if.if, label %B13409637.endif.endif.us.us, !prof !0

B13409637.endif.endif.us.us:                      ; preds = %B13409637.us.us
  %95 = icmp slt i64 %arg.y.2, 1
  %.806.us.us = getelementptr double, ptr %arg.K.4, i64 %arg.K.5.1
  %.834.fca.4.insert.us.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us.us, 4
  %.834.fca.5.0.insert.us.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us.us, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us.us, i64 %arg.K.6.1, 6, 0
  %.875.us.us = call ptr @PyLong_AsVoidPtr(ptr nonnull %.867.us.us)
  call void @Py_DecRef(ptr nonnull %.867.us.us)
  call void @numba_gil_release(ptr nonnull %.854)
  %.885.us.us = call double %.875.us.us({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us.us)
  %.10.i = fcmp olt double %.885.us.us, %.278.0
  %.11.i = select i1 %.10.i, double %.885.us.us, double %.278.0
  br i1 %95, label %B13409637.us.us.1, label %iter.check327

iter.check327:                                    ; preds = %B13409637.endif.endif.us.us
  %96 = getelementptr double, ptr %.172, i64 %arg.y.2
  %min.iters.check325 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check325, label %B13409633.us.us.1.preheader, label %vector.memcheck319

vector.memcheck319:                               ; preds = %iter.check327
  %97 = ptrtoint ptr %.172 to i64
  %98 = ptrtoint ptr %arg.ytmp.4 to i64
  %99 = ptrtoint ptr %arg.y.4 to i64
  %100 = sub i64 %98, %99
  %diff.check322 = icmp ult i64 %100, 256
  %101 = shl i64 %arg.y.2, 3
  %102 = add i64 %101, %97
  %103 = sub i64 %98, %102
  %diff.check323 = icmp ult i64 %103, 256
  %conflict.rdx324 = or i1 %diff.check322, %diff.check323
  br i1 %conflict.rdx324, label %B13409633.us.us.1.preheader, label %vector.main.loop.iter.check329

vector.main.loop.iter.check329:                   ; preds = %vector.memcheck319
  %const764 = bitcast i64 9223372036854775776 to i64
  %min.iters.check328 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check328, label %vec.epilog.ph352, label %vector.ph330

vector.ph330:                                     ; preds = %vector.main.loop.iter.check329
  %n.vec332 = and i64 %arg.y.2, %const764
  %broadcast.splatinsert333 = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat334 = shufflevector <8 x double> %broadcast.splatinsert333, <8 x double> poison, <8 x i32> zeroinitializer
  %104 = getelementptr i8, ptr %.172, i64 %101
  %scevgep816 = getelementptr i8, ptr %104, i64 192
  br label %vector.body335

vector.body335:                                   ; preds = %vector.body335, %vector.ph330
  %index336 = phi i64 [ 0, %vector.ph330 ], [ %index.next345, %vector.body335 ]
  %sunkaddr936 = mul i64 %index336, 8
  %sunkaddr937 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr936
  %wide.load337 = load <8 x double>, ptr %sunkaddr937, align 8
  %sunkaddr938 = mul i64 %index336, 8
  %sunkaddr939 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr938
  %sunkaddr940 = getelementptr i8, ptr %sunkaddr939, i64 64
  %wide.load338 = load <8 x double>, ptr %sunkaddr940, align 8
  %sunkaddr941 = mul i64 %index336, 8
  %sunkaddr942 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr941
  %sunkaddr943 = getelementptr i8, ptr %sunkaddr942, i64 128
  %wide.load339 = load <8 x double>, ptr %sunkaddr943, align 8
  %sunkaddr944 = mul i64 %index336, 8
  %sunkaddr945 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr944
  %sunkaddr946 = getelementptr i8, ptr %sunkaddr945, i64 192
  %wide.load340 = load <8 x double>, ptr %sunkaddr946, align 8
  %105 = shl i64 %index336, 3
  %scevgep229 = getelementptr i8, ptr %scevgep816, i64 %105
  %scevgep232 = getelementptr i8, ptr %scevgep229, i64 -192
  %scevgep231 = getelementptr i8, ptr %scevgep229, i64 -128
  %scevgep230 = getelementptr i8, ptr %scevgep229, i64 -64
  %wide.load341 = load <8 x double>, ptr %scevgep232, align 8
  %wide.load342 = load <8 x double>, ptr %scevgep231, align 8
  %wide.load343 = load <8 x double>, ptr %scevgep230, align 8
  %wide.load344 = load <8 x double>, ptr %scevgep229, align 8
  %106 = fmul <8 x double> %broadcast.splat334, %wide.load341
  %107 = fmul <8 x double> %broadcast.splat334, %wide.load342
  %108 = fmul <8 x double> %broadcast.splat334, %wide.load343
  %109 = fmul <8 x double> %broadcast.splat334, %wide.load344
  %110 = fadd <8 x double> %wide.load337, %106
  %111 = fadd <8 x double> %wide.load338, %107
  %112 = fadd <8 x double> %wide.load339, %108
  %113 = fadd <8 x double> %wide.load340, %109
  %sunkaddr947 = mul i64 %index336, 8
  %sunkaddr948 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr947
  store <8 x double> %110, ptr %sunkaddr948, align 8
  %sunkaddr949 = mul i64 %index336, 8
  %sunkaddr950 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr949
  %sunkaddr951 = getelementptr i8, ptr %sunkaddr950, i64 64
  store <8 x double> %111, ptr %sunkaddr951, align 8
  %sunkaddr952 = mul i64 %index336, 8
  %sunkaddr953 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr952
  %sunkaddr954 = getelementptr i8, ptr %sunkaddr953, i64 128
  store <8 x double> %112, ptr %sunkaddr954, align 8
  %sunkaddr955 = mul i64 %index336, 8
  %sunkaddr956 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr955
  %sunkaddr957 = getelementptr i8, ptr %sunkaddr956, i64 192
  store <8 x double> %113, ptr %sunkaddr957, align 8
  %index.next345 = add nuw nsw i64 %index336, 32
  %114 = icmp eq i64 %n.vec332, %index.next345
  br i1 %114, label %middle.block346, label %vector.body335, !llvm.loop !33

middle.block346:                                  ; preds = %vector.body335
  %cmp.n347 = icmp eq i64 %arg.y.2, %n.vec332
  br i1 %cmp.n347, label %B13409637.us.us.1, label %vec.epilog.iter.check350

vec.epilog.iter.check350:                         ; preds = %middle.block346
  %115 = and i64 %arg.y.2, 28
  %min.epilog.iters.check351 = icmp eq i64 %115, 0
  br i1 %min.epilog.iters.check351, label %B13409633.us.us.1.preheader, label %vec.epilog.ph352, !prof !9

vec.epilog.ph352:                                 ; preds = %vec.epilog.iter.check350, %vector.main.loop.iter.check329
  %vec.epilog.resume.val348 = phi i64 [ %n.vec332, %vec.epilog.iter.check350 ], [ 0, %vector.main.loop.iter.check329 ]
  %const_mat765 = add i64 %const764, 28
  %n.vec354 = and i64 %arg.y.2, %const_mat765
  %broadcast.splatinsert355 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat356 = shufflevector <4 x double> %broadcast.splatinsert355, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body357

vec.epilog.vector.body357:                        ; preds = %vec.epilog.vector.body357, %vec.epilog.ph352
  %index358 = phi i64 [ %vec.epilog.resume.val348, %vec.epilog.ph352 ], [ %index.next361, %vec.epilog.vector.body357 ]
  %116 = shl i64 %index358, 3
  %scevgep807 = getelementptr i8, ptr %arg.y.4, i64 %116
  %wide.load359 = load <4 x double>, ptr %scevgep807, align 8
  %scevgep806 = getelementptr i8, ptr %96, i64 %116
  %wide.load360 = load <4 x double>, ptr %scevgep806, align 8
  %117 = fmul <4 x double> %broadcast.splat356, %wide.load360
  %118 = fadd <4 x double> %wide.load359, %117
  %119 = shl i64 %index358, 3
  %scevgep220 = getelementptr i8, ptr %arg.ytmp.4, i64 %119
  store <4 x double> %118, ptr %scevgep220, align 8
  %index.next361 = add nuw i64 %index358, 4
  %120 = icmp eq i64 %n.vec354, %index.next361
  br i1 %120, label %vec.epilog.middle.block362, label %vec.epilog.vector.body357, !llvm.loop !34

vec.epilog.middle.block362:                       ; preds = %vec.epilog.vector.body357
  %cmp.n363 = icmp eq i64 %arg.y.2, %n.vec354
  br i1 %cmp.n363, label %B13409637.us.us.1, label %B13409633.us.us.1.preheader

B13409633.us.us.1.preheader:                      ; preds = %vec.epilog.middle.block362, %vec.epilog.iter.check350, %vector.memcheck319, %iter.check327
  %.632619621.us.us.1.ph = phi i64 [ 0, %iter.check327 ], [ 0, %vector.memcheck319 ], [ %n.vec332, %vec.epilog.iter.check350 ], [ %n.vec354, %vec.epilog.middle.block362 ]
  %121 = sub nsw i64 %arg.y.2, %.632619621.us.us.1.ph
  %xtraiter556 = and i64 %121, 7
  %lcmp.mod557.not = icmp eq i64 %xtraiter556, 0
  br i1 %lcmp.mod557.not, label %B13409633.us.us.1.prol.loopexit, label %B13409633.us.us.1.prol.preheader

B13409633.us.us.1.prol.preheader:                 ; preds = %B13409633.us.us.1.preheader
  br label %B13409633.us.us.1.prol

B13409633.us.us.1.prol:                           ; preds = %B13409633.us.us.1.prol.preheader, %B13409633.us.us.1.prol
  %lsr.iv803 = phi i64 [ %lsr.iv.next804, %B13409633.us.us.1.prol ], [ %xtraiter556, %B13409633.us.us.1.prol.preheader ]
  %.632619621.us.us.1.prol = phi i64 [ %.639.us.us.1.prol, %B13409633.us.us.1.prol ], [ %.632619621.us.us.1.ph, %B13409633.us.us.1.prol.preheader ]
  %.639.us.us.1.prol = add nuw i64 %.632619621.us.us.1.prol, 1
  %122 = shl i64 %.632619621.us.us.1.prol, 3
  %scevgep802 = getelementptr i8, ptr %arg.y.4, i64 %122
  %.691.us.us.1.prol = load double, ptr %scevgep802, align 8
  %scevgep801 = getelementptr i8, ptr %96, i64 %122
  %.720.us.us.1.prol = load double, ptr %scevgep801, align 8
  %.722.us.us.1.prol = fmul double %.524.us.us, %.720.us.us.1.prol
  %.723.us.us.1.prol = fadd double %.691.us.us.1.prol, %.722.us.us.1.prol
  %123 = shl i64 %.632619621.us.us.1.prol, 3
  %scevgep219 = getelementptr i8, ptr %arg.ytmp.4, i64 %123
  store double %.723.us.us.1.prol, ptr %scevgep219, align 8
  %lsr.iv.next804 = add nsw i64 %lsr.iv803, -1
  %prol.iter558.cmp.not = icmp eq i64 %lsr.iv.next804, 0
  br i1 %prol.iter558.cmp.not, label %B13409633.us.us.1.prol.loopexit, label %B13409633.us.us.1.prol, !llvm.loop !35

B13409633.us.us.1.prol.loopexit:                  ; preds = %B13409633.us.us.1.prol, %B13409633.us.us.1.preheader
  %.632619621.us.us.1.unr = phi i64 [ %.632619621.us.us.1.ph, %B13409633.us.us.1.preheader ], [ %.639.us.us.1.prol, %B13409633.us.us.1.prol ]
  %124 = sub nsw i64 %.632619621.us.us.1.ph, %arg.y.2
  %125 = icmp ugt i64 %124, -8
  br i1 %125, label %B13409637.us.us.1, label %B13409633.us.us.1.preheader567

B13409633.us.us.1.preheader567:                   ; preds = %B13409633.us.us.1.prol.loopexit
  %126 = shl i64 %arg.y.2, 3
  %127 = getelementptr i8, ptr %.172, i64 %126
  %scevgep768 = getelementptr i8, ptr %127, i64 56
  br label %B13409633.us.us.1

B13409633.us.us.1:                                ; preds = %B13409633.us.us.1, %B13409633.us.us.1.preheader567
  %.632619621.us.us.1 = phi i64 [ %.639.us.us.1.7, %B13409633.us.us.1 ], [ %.632619621.us.us.1.unr, %B13409633.us.us.1.preheader567 ]
  %sunkaddr1600 = shl i64 %.632619621.us.us.1, 3
  %sunkaddr958 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr959 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr958
  %.691.us.us.1 = load double, ptr %sunkaddr959, align 8
  %scevgep780 = getelementptr i8, ptr %scevgep768, i64 %sunkaddr1600
  %scevgep781 = getelementptr i8, ptr %scevgep780, i64 -56
  %.720.us.us.1 = load double, ptr %scevgep781, align 8
  %.722.us.us.1 = fmul double %.524.us.us, %.720.us.us.1
  %.723.us.us.1 = fadd double %.691.us.us.1, %.722.us.us.1
  %sunkaddr960 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr961 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr960
  store double %.723.us.us.1, ptr %sunkaddr961, align 8
  %sunkaddr962 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr963 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr962
  %sunkaddr964 = getelementptr i8, ptr %sunkaddr963, i64 8
  %.691.us.us.1.1 = load double, ptr %sunkaddr964, align 8
  %128 = shl i64 %.632619621.us.us.1, 3
  %scevgep201 = getelementptr i8, ptr %scevgep768, i64 %128
  %scevgep202 = getelementptr i8, ptr %scevgep201, i64 -48
  %.720.us.us.1.1 = load double, ptr %scevgep202, align 8
  %.722.us.us.1.1 = fmul double %.524.us.us, %.720.us.us.1.1
  %.723.us.us.1.1 = fadd double %.691.us.us.1.1, %.722.us.us.1.1
  %sunkaddr965 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr966 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr965
  %sunkaddr967 = getelementptr i8, ptr %sunkaddr966, i64 8
  store double %.723.us.us.1.1, ptr %sunkaddr967, align 8
  %sunkaddr968 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr969 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr968
  %sunkaddr970 = getelementptr i8, ptr %sunkaddr969, i64 16
  %.691.us.us.1.2 = load double, ptr %sunkaddr970, align 8
  %129 = shl i64 %.632619621.us.us.1, 3
  %scevgep199 = getelementptr i8, ptr %scevgep768, i64 %129
  %scevgep200 = getelementptr i8, ptr %scevgep199, i64 -40
  %.720.us.us.1.2 = load double, ptr %scevgep200, align 8
  %.722.us.us.1.2 = fmul double %.524.us.us, %.720.us.us.1.2
  %.723.us.us.1.2 = fadd double %.691.us.us.1.2, %.722.us.us.1.2
  %sunkaddr971 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr972 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr971
  %sunkaddr973 = getelementptr i8, ptr %sunkaddr972, i64 16
  store double %.723.us.us.1.2, ptr %sunkaddr973, align 8
  %sunkaddr974 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr975 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr974
  %sunkaddr976 = getelementptr i8, ptr %sunkaddr975, i64 24
  %.691.us.us.1.3 = load double, ptr %sunkaddr976, align 8
  %130 = shl i64 %.632619621.us.us.1, 3
  %scevgep197 = getelementptr i8, ptr %scevgep768, i64 %130
  %scevgep198 = getelementptr i8, ptr %scevgep197, i64 -32
  %.720.us.us.1.3 = load double, ptr %scevgep198, align 8
  %.722.us.us.1.3 = fmul double %.524.us.us, %.720.us.us.1.3
  %.723.us.us.1.3 = fadd double %.691.us.us.1.3, %.722.us.us.1.3
  %sunkaddr977 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr978 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr977
  %sunkaddr979 = getelementptr i8, ptr %sunkaddr978, i64 24
  store double %.723.us.us.1.3, ptr %sunkaddr979, align 8
  %sunkaddr980 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr981 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr980
  %sunkaddr982 = getelementptr i8, ptr %sunkaddr981, i64 32
  %.691.us.us.1.4 = load double, ptr %sunkaddr982, align 8
  %131 = shl i64 %.632619621.us.us.1, 3
  %scevgep195 = getelementptr i8, ptr %scevgep768, i64 %131
  %scevgep196 = getelementptr i8, ptr %scevgep195, i64 -24
  %.720.us.us.1.4 = load double, ptr %scevgep196, align 8
  %.722.us.us.1.4 = fmul double %.524.us.us, %.720.us.us.1.4
  %.723.us.us.1.4 = fadd double %.691.us.us.1.4, %.722.us.us.1.4
  %sunkaddr983 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr984 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr983
  %sunkaddr985 = getelementptr i8, ptr %sunkaddr984, i64 32
  store double %.723.us.us.1.4, ptr %sunkaddr985, align 8
  %sunkaddr986 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr987 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr986
  %sunkaddr988 = getelementptr i8, ptr %sunkaddr987, i64 40
  %.691.us.us.1.5 = load double, ptr %sunkaddr988, align 8
  %132 = shl i64 %.632619621.us.us.1, 3
  %scevgep193 = getelementptr i8, ptr %scevgep768, i64 %132
  %scevgep194 = getelementptr i8, ptr %scevgep193, i64 -16
  %.720.us.us.1.5 = load double, ptr %scevgep194, align 8
  %.722.us.us.1.5 = fmul double %.524.us.us, %.720.us.us.1.5
  %.723.us.us.1.5 = fadd double %.691.us.us.1.5, %.722.us.us.1.5
  %sunkaddr989 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr990 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr989
  %sunkaddr991 = getelementptr i8, ptr %sunkaddr990, i64 40
  store double %.723.us.us.1.5, ptr %sunkaddr991, align 8
  %sunkaddr992 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr993 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr992
  %sunkaddr994 = getelementptr i8, ptr %sunkaddr993, i64 48
  %.691.us.us.1.6 = load double, ptr %sunkaddr994, align 8
  %133 = shl i64 %.632619621.us.us.1, 3
  %scevgep191 = getelementptr i8, ptr %scevgep768, i64 %133
  %scevgep192 = getelementptr i8, ptr %scevgep191, i64 -8
  %.720.us.us.1.6 = load double, ptr %scevgep192, align 8
  %.722.us.us.1.6 = fmul double %.524.us.us, %.720.us.us.1.6
  %.723.us.us.1.6 = fadd double %.691.us.us.1.6, %.722.us.us.1.6
  %sunkaddr995 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr996 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr995
  %sunkaddr997 = getelementptr i8, ptr %sunkaddr996, i64 48
  store double %.723.us.us.1.6, ptr %sunkaddr997, align 8
  %.639.us.us.1.7 = add nuw nsw i64 %.632619621.us.us.1, 8
  %sunkaddr998 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr999 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr998
  %sunkaddr1000 = getelementptr i8, ptr %sunkaddr999, i64 56
  %.691.us.us.1.7 = load double, ptr %sunkaddr1000, align 8
  %.720.us.us.1.7 = load double, ptr %scevgep780, align 8
  %.722.us.us.1.7 = fmul double %.524.us.us, %.720.us.us.1.7
  %.723.us.us.1.7 = fadd double %.691.us.us.1.7, %.722.us.us.1.7
  %sunkaddr1001 = mul i64 %.632619621.us.us.1, 8
  %sunkaddr1002 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1001
  %sunkaddr1003 = getelementptr i8, ptr %sunkaddr1002, i64 56
  store double %.723.us.us.1.7, ptr %sunkaddr1003, align 8
  %exitcond689.1.not.7 = icmp eq i64 %arg.y.2, %.639.us.us.1.7
  br i1 %exitcond689.1.not.7, label %B13409637.us.us.1, label %B13409633.us.us.1, !llvm.loop !36

B13409637.us.us.1:                                ; preds = %B13409633.us.us.1, %B13409633.us.us.1.prol.loopexit, %vec.epilog.middle.block362, %middle.block346, %B13409637.endif.endif.us.us
  call void @numba_gil_ensure(ptr nonnull %.854)
  %.857.us.us.1 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.17)
  %.858.us.us.1 = call ptr @PyObject_GetAttrString(ptr %.857.us.us.1, ptr nonnull @.const._get_wrapper_address.18)
  call void @Py_DecRef(ptr %.857.us.us.1)
  %.866.us.us.1 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.19, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.20)
  %.867.us.us.1 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.858.us.us.1, ptr %arg.f.1, ptr %.866.us.us.1, ptr null)
  %.868.us.us.1 = icmp eq ptr %.867.us.us.1, null
  br i1 %.868.us.us.1, label %B13409637.if.if.if, label %B13409637.endif.endif.us.us.1, !prof !0

B13409637.endif.endif.us.us.1:                    ; preds = %B13409637.us.us.1
  %134 = icmp slt i64 %arg.y.2, 1
  %.806.us.us.1.idx = shl i64 %arg.K.5.1, 4
  %.806.us.us.1 = getelementptr i8, ptr %arg.K.4, i64 %.806.us.us.1.idx
  %.834.fca.4.insert.us.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us.us.1, 4
  %.834.fca.5.0.insert.us.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us.us.1, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us.us.1, i64 %arg.K.6.1, 6, 0
  %.875.us.us.1 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.867.us.us.1)
  call void @Py_DecRef(ptr nonnull %.867.us.us.1)
  call void @numba_gil_release(ptr nonnull %.854)
  %.885.us.us.1 = call double %.875.us.us.1({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us.us.1)
  %.10.i1 = fcmp olt double %.885.us.us.1, %.11.i
  %.11.i2 = select i1 %.10.i1, double %.885.us.us.1, double %.11.i
  br i1 %134, label %B13409637.us.us.2, label %iter.check373

iter.check373:                                    ; preds = %B13409637.endif.endif.us.us.1
  %.idx693 = shl i64 %arg.y.2, 4
  %135 = getelementptr i8, ptr %.172, i64 %.idx693
  %min.iters.check371 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check371, label %B13409633.us.us.2.preheader, label %vector.memcheck365

vector.memcheck365:                               ; preds = %iter.check373
  %136 = ptrtoint ptr %.172 to i64
  %137 = ptrtoint ptr %arg.ytmp.4 to i64
  %138 = ptrtoint ptr %arg.y.4 to i64
  %139 = sub i64 %137, %138
  %diff.check368 = icmp ult i64 %139, 256
  %140 = add i64 %.idx693, %136
  %141 = sub i64 %137, %140
  %diff.check369 = icmp ult i64 %141, 256
  %conflict.rdx370 = or i1 %diff.check368, %diff.check369
  br i1 %conflict.rdx370, label %B13409633.us.us.2.preheader, label %vector.main.loop.iter.check375

vector.main.loop.iter.check375:                   ; preds = %vector.memcheck365
  %const766 = bitcast i64 9223372036854775776 to i64
  %min.iters.check374 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check374, label %vec.epilog.ph398, label %vector.ph376

vector.ph376:                                     ; preds = %vector.main.loop.iter.check375
  %n.vec378 = and i64 %arg.y.2, %const766
  %broadcast.splatinsert379 = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat380 = shufflevector <8 x double> %broadcast.splatinsert379, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body381

vector.body381:                                   ; preds = %vector.body381, %vector.ph376
  %index382 = phi i64 [ 0, %vector.ph376 ], [ %index.next391, %vector.body381 ]
  %sunkaddr1004 = mul i64 %index382, 8
  %sunkaddr1005 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1004
  %wide.load383 = load <8 x double>, ptr %sunkaddr1005, align 8
  %sunkaddr1006 = mul i64 %index382, 8
  %sunkaddr1007 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1006
  %sunkaddr1008 = getelementptr i8, ptr %sunkaddr1007, i64 64
  %wide.load384 = load <8 x double>, ptr %sunkaddr1008, align 8
  %sunkaddr1009 = mul i64 %index382, 8
  %sunkaddr1010 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1009
  %sunkaddr1011 = getelementptr i8, ptr %sunkaddr1010, i64 128
  %wide.load385 = load <8 x double>, ptr %sunkaddr1011, align 8
  %sunkaddr1012 = mul i64 %index382, 8
  %sunkaddr1013 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1012
  %sunkaddr1014 = getelementptr i8, ptr %sunkaddr1013, i64 192
  %wide.load386 = load <8 x double>, ptr %sunkaddr1014, align 8
  %sunkaddr1015 = mul i64 %index382, 8
  %sunkaddr1016 = getelementptr i8, ptr %135, i64 %sunkaddr1015
  %wide.load387 = load <8 x double>, ptr %sunkaddr1016, align 8
  %sunkaddr1017 = mul i64 %index382, 8
  %sunkaddr1018 = getelementptr i8, ptr %135, i64 %sunkaddr1017
  %sunkaddr1019 = getelementptr i8, ptr %sunkaddr1018, i64 64
  %wide.load388 = load <8 x double>, ptr %sunkaddr1019, align 8
  %sunkaddr1020 = mul i64 %index382, 8
  %sunkaddr1021 = getelementptr i8, ptr %135, i64 %sunkaddr1020
  %sunkaddr1022 = getelementptr i8, ptr %sunkaddr1021, i64 128
  %wide.load389 = load <8 x double>, ptr %sunkaddr1022, align 8
  %sunkaddr1023 = mul i64 %index382, 8
  %sunkaddr1024 = getelementptr i8, ptr %135, i64 %sunkaddr1023
  %sunkaddr1025 = getelementptr i8, ptr %sunkaddr1024, i64 192
  %wide.load390 = load <8 x double>, ptr %sunkaddr1025, align 8
  %142 = fmul <8 x double> %broadcast.splat380, %wide.load387
  %143 = fmul <8 x double> %broadcast.splat380, %wide.load388
  %144 = fmul <8 x double> %broadcast.splat380, %wide.load389
  %145 = fmul <8 x double> %broadcast.splat380, %wide.load390
  %146 = fadd <8 x double> %wide.load383, %142
  %147 = fadd <8 x double> %wide.load384, %143
  %148 = fadd <8 x double> %wide.load385, %144
  %149 = fadd <8 x double> %wide.load386, %145
  %sunkaddr1026 = mul i64 %index382, 8
  %sunkaddr1027 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1026
  store <8 x double> %146, ptr %sunkaddr1027, align 8
  %sunkaddr1028 = mul i64 %index382, 8
  %sunkaddr1029 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1028
  %sunkaddr1030 = getelementptr i8, ptr %sunkaddr1029, i64 64
  store <8 x double> %147, ptr %sunkaddr1030, align 8
  %sunkaddr1031 = mul i64 %index382, 8
  %sunkaddr1032 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1031
  %sunkaddr1033 = getelementptr i8, ptr %sunkaddr1032, i64 128
  store <8 x double> %148, ptr %sunkaddr1033, align 8
  %sunkaddr1034 = mul i64 %index382, 8
  %sunkaddr1035 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1034
  %sunkaddr1036 = getelementptr i8, ptr %sunkaddr1035, i64 192
  store <8 x double> %149, ptr %sunkaddr1036, align 8
  %index.next391 = add nuw nsw i64 %index382, 32
  %150 = icmp eq i64 %n.vec378, %index.next391
  br i1 %150, label %middle.block392, label %vector.body381, !llvm.loop !37

middle.block392:                                  ; preds = %vector.body381
  %cmp.n393 = icmp eq i64 %arg.y.2, %n.vec378
  br i1 %cmp.n393, label %B13409637.us.us.2, label %vec.epilog.iter.check396

vec.epilog.iter.check396:                         ; preds = %middle.block392
  %151 = and i64 %arg.y.2, 28
  %min.epilog.iters.check397 = icmp eq i64 %151, 0
  br i1 %min.epilog.iters.check397, label %B13409633.us.us.2.preheader, label %vec.epilog.ph398, !prof !9

vec.epilog.ph398:                                 ; preds = %vec.epilog.iter.check396, %vector.main.loop.iter.check375
  %vec.epilog.resume.val394 = phi i64 [ %n.vec378, %vec.epilog.iter.check396 ], [ 0, %vector.main.loop.iter.check375 ]
  %const_mat767 = add i64 %const766, 28
  %n.vec400 = and i64 %arg.y.2, %const_mat767
  %broadcast.splatinsert401 = insertelement <4 x double> poison, double %arg.h, i64 0
  %broadcast.splat402 = shufflevector <4 x double> %broadcast.splatinsert401, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body403

vec.epilog.vector.body403:                        ; preds = %vec.epilog.vector.body403, %vec.epilog.ph398
  %index404 = phi i64 [ %vec.epilog.resume.val394, %vec.epilog.ph398 ], [ %index.next407, %vec.epilog.vector.body403 ]
  %152 = shl i64 %index404, 3
  %scevgep727 = getelementptr i8, ptr %arg.y.4, i64 %152
  %wide.load405 = load <4 x double>, ptr %scevgep727, align 8
  %scevgep726 = getelementptr i8, ptr %135, i64 %152
  %wide.load406 = load <4 x double>, ptr %scevgep726, align 8
  %153 = fmul <4 x double> %broadcast.splat402, %wide.load406
  %154 = fadd <4 x double> %wide.load405, %153
  %155 = shl i64 %index404, 3
  %scevgep154 = getelementptr i8, ptr %arg.ytmp.4, i64 %155
  store <4 x double> %154, ptr %scevgep154, align 8
  %index.next407 = add nuw i64 %index404, 4
  %156 = icmp eq i64 %n.vec400, %index.next407
  br i1 %156, label %vec.epilog.middle.block408, label %vec.epilog.vector.body403, !llvm.loop !38

vec.epilog.middle.block408:                       ; preds = %vec.epilog.vector.body403
  %cmp.n409 = icmp eq i64 %arg.y.2, %n.vec400
  br i1 %cmp.n409, label %B13409637.us.us.2, label %B13409633.us.us.2.preheader

B13409633.us.us.2.preheader:                      ; preds = %vec.epilog.middle.block408, %vec.epilog.iter.check396, %vector.memcheck365, %iter.check373
  %.632619621.us.us.2.ph = phi i64 [ 0, %iter.check373 ], [ 0, %vector.memcheck365 ], [ %n.vec378, %vec.epilog.iter.check396 ], [ %n.vec400, %vec.epilog.middle.block408 ]
  %157 = sub nsw i64 %arg.y.2, %.632619621.us.us.2.ph
  %xtraiter559 = and i64 %157, 7
  %lcmp.mod560.not = icmp eq i64 %xtraiter559, 0
  br i1 %lcmp.mod560.not, label %B13409633.us.us.2.prol.loopexit, label %B13409633.us.us.2.prol.preheader

B13409633.us.us.2.prol.preheader:                 ; preds = %B13409633.us.us.2.preheader
  br label %B13409633.us.us.2.prol

B13409633.us.us.2.prol:                           ; preds = %B13409633.us.us.2.prol.preheader, %B13409633.us.us.2.prol
  %lsr.iv723 = phi i64 [ %lsr.iv.next724, %B13409633.us.us.2.prol ], [ %xtraiter559, %B13409633.us.us.2.prol.preheader ]
  %.632619621.us.us.2.prol = phi i64 [ %.639.us.us.2.prol, %B13409633.us.us.2.prol ], [ %.632619621.us.us.2.ph, %B13409633.us.us.2.prol.preheader ]
  %.639.us.us.2.prol = add nuw i64 %.632619621.us.us.2.prol, 1
  %158 = shl i64 %.632619621.us.us.2.prol, 3
  %scevgep722 = getelementptr i8, ptr %arg.y.4, i64 %158
  %.691.us.us.2.prol = load double, ptr %scevgep722, align 8
  %scevgep721 = getelementptr i8, ptr %135, i64 %158
  %.720.us.us.2.prol = load double, ptr %scevgep721, align 8
  %.722.us.us.2.prol = fmul double %arg.h, %.720.us.us.2.prol
  %.723.us.us.2.prol = fadd double %.691.us.us.2.prol, %.722.us.us.2.prol
  %159 = shl i64 %.632619621.us.us.2.prol, 3
  %scevgep153 = getelementptr i8, ptr %arg.ytmp.4, i64 %159
  store double %.723.us.us.2.prol, ptr %scevgep153, align 8
  %lsr.iv.next724 = add nsw i64 %lsr.iv723, -1
  %prol.iter561.cmp.not = icmp eq i64 %lsr.iv.next724, 0
  br i1 %prol.iter561.cmp.not, label %B13409633.us.us.2.prol.loopexit, label %B13409633.us.us.2.prol, !llvm.loop !39

B13409633.us.us.2.prol.loopexit:                  ; preds = %B13409633.us.us.2.prol, %B13409633.us.us.2.preheader
  %.632619621.us.us.2.unr = phi i64 [ %.632619621.us.us.2.ph, %B13409633.us.us.2.preheader ], [ %.639.us.us.2.prol, %B13409633.us.us.2.prol ]
  %160 = sub nsw i64 %.632619621.us.us.2.ph, %arg.y.2
  %161 = icmp ugt i64 %160, -8
  br i1 %161, label %B13409637.us.us.2, label %B13409633.us.us.2.preheader566

B13409633.us.us.2.preheader566:                   ; preds = %B13409633.us.us.2.prol.loopexit
  %scevgep688 = getelementptr i8, ptr %135, i64 56
  br label %B13409633.us.us.2

B13409633.us.us.2:                                ; preds = %B13409633.us.us.2, %B13409633.us.us.2.preheader566
  %.632619621.us.us.2 = phi i64 [ %.639.us.us.2.7, %B13409633.us.us.2 ], [ %.632619621.us.us.2.unr, %B13409633.us.us.2.preheader566 ]
  %sunkaddr1668 = shl i64 %.632619621.us.us.2, 3
  %sunkaddr1037 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1038 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1037
  %.691.us.us.2 = load double, ptr %sunkaddr1038, align 8
  %scevgep700 = getelementptr i8, ptr %scevgep688, i64 %sunkaddr1668
  %scevgep701 = getelementptr i8, ptr %scevgep700, i64 -56
  %.720.us.us.2 = load double, ptr %scevgep701, align 8
  %.722.us.us.2 = fmul double %arg.h, %.720.us.us.2
  %.723.us.us.2 = fadd double %.691.us.us.2, %.722.us.us.2
  %sunkaddr1039 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1040 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1039
  store double %.723.us.us.2, ptr %sunkaddr1040, align 8
  %sunkaddr1041 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1042 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1041
  %sunkaddr1043 = getelementptr i8, ptr %sunkaddr1042, i64 8
  %.691.us.us.2.1 = load double, ptr %sunkaddr1043, align 8
  %162 = shl i64 %.632619621.us.us.2, 3
  %scevgep135 = getelementptr i8, ptr %scevgep688, i64 %162
  %scevgep136 = getelementptr i8, ptr %scevgep135, i64 -48
  %.720.us.us.2.1 = load double, ptr %scevgep136, align 8
  %.722.us.us.2.1 = fmul double %arg.h, %.720.us.us.2.1
  %.723.us.us.2.1 = fadd double %.691.us.us.2.1, %.722.us.us.2.1
  %sunkaddr1044 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1045 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1044
  %sunkaddr1046 = getelementptr i8, ptr %sunkaddr1045, i64 8
  store double %.723.us.us.2.1, ptr %sunkaddr1046, align 8
  %sunkaddr1047 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1048 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1047
  %sunkaddr1049 = getelementptr i8, ptr %sunkaddr1048, i64 16
  %.691.us.us.2.2 = load double, ptr %sunkaddr1049, align 8
  %163 = shl i64 %.632619621.us.us.2, 3
  %scevgep133 = getelementptr i8, ptr %scevgep688, i64 %163
  %scevgep134 = getelementptr i8, ptr %scevgep133, i64 -40
  %.720.us.us.2.2 = load double, ptr %scevgep134, align 8
  %.722.us.us.2.2 = fmul double %arg.h, %.720.us.us.2.2
  %.723.us.us.2.2 = fadd double %.691.us.us.2.2, %.722.us.us.2.2
  %sunkaddr1050 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1051 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1050
  %sunkaddr1052 = getelementptr i8, ptr %sunkaddr1051, i64 16
  store double %.723.us.us.2.2, ptr %sunkaddr1052, align 8
  %sunkaddr1053 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1054 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1053
  %sunkaddr1055 = getelementptr i8, ptr %sunkaddr1054, i64 24
  %.691.us.us.2.3 = load double, ptr %sunkaddr1055, align 8
  %164 = shl i64 %.632619621.us.us.2, 3
  %scevgep131 = getelementptr i8, ptr %scevgep688, i64 %164
  %scevgep132 = getelementptr i8, ptr %scevgep131, i64 -32
  %.720.us.us.2.3 = load double, ptr %scevgep132, align 8
  %.722.us.us.2.3 = fmul double %arg.h, %.720.us.us.2.3
  %.723.us.us.2.3 = fadd double %.691.us.us.2.3, %.722.us.us.2.3
  %sunkaddr1056 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1057 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1056
  %sunkaddr1058 = getelementptr i8, ptr %sunkaddr1057, i64 24
  store double %.723.us.us.2.3, ptr %sunkaddr1058, align 8
  %sunkaddr1059 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1060 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1059
  %sunkaddr1061 = getelementptr i8, ptr %sunkaddr1060, i64 32
  %.691.us.us.2.4 = load double, ptr %sunkaddr1061, align 8
  %165 = shl i64 %.632619621.us.us.2, 3
  %scevgep129 = getelementptr i8, ptr %scevgep688, i64 %165
  %scevgep130 = getelementptr i8, ptr %scevgep129, i64 -24
  %.720.us.us.2.4 = load double, ptr %scevgep130, align 8
  %.722.us.us.2.4 = fmul double %arg.h, %.720.us.us.2.4
  %.723.us.us.2.4 = fadd double %.691.us.us.2.4, %.722.us.us.2.4
  %sunkaddr1062 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1063 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1062
  %sunkaddr1064 = getelementptr i8, ptr %sunkaddr1063, i64 32
  store double %.723.us.us.2.4, ptr %sunkaddr1064, align 8
  %sunkaddr1065 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1066 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1065
  %sunkaddr1067 = getelementptr i8, ptr %sunkaddr1066, i64 40
  %.691.us.us.2.5 = load double, ptr %sunkaddr1067, align 8
  %166 = shl i64 %.632619621.us.us.2, 3
  %scevgep127 = getelementptr i8, ptr %scevgep688, i64 %166
  %scevgep128 = getelementptr i8, ptr %scevgep127, i64 -16
  %.720.us.us.2.5 = load double, ptr %scevgep128, align 8
  %.722.us.us.2.5 = fmul double %arg.h, %.720.us.us.2.5
  %.723.us.us.2.5 = fadd double %.691.us.us.2.5, %.722.us.us.2.5
  %sunkaddr1068 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1069 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1068
  %sunkaddr1070 = getelementptr i8, ptr %sunkaddr1069, i64 40
  store double %.723.us.us.2.5, ptr %sunkaddr1070, align 8
  %sunkaddr1071 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1072 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1071
  %sunkaddr1073 = getelementptr i8, ptr %sunkaddr1072, i64 48
  %.691.us.us.2.6 = load double, ptr %sunkaddr1073, align 8
  %167 = shl i64 %.632619621.us.us.2, 3
  %scevgep125 = getelementptr i8, ptr %scevgep688, i64 %167
  %scevgep126 = getelementptr i8, ptr %scevgep125, i64 -8
  %.720.us.us.2.6 = load double, ptr %scevgep126, align 8
  %.722.us.us.2.6 = fmul double %arg.h, %.720.us.us.2.6
  %.723.us.us.2.6 = fadd double %.691.us.us.2.6, %.722.us.us.2.6
  %sunkaddr1074 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1075 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1074
  %sunkaddr1076 = getelementptr i8, ptr %sunkaddr1075, i64 48
  store double %.723.us.us.2.6, ptr %sunkaddr1076, align 8
  %.639.us.us.2.7 = add nuw nsw i64 %.632619621.us.us.2, 8
  %sunkaddr1077 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1078 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1077
  %sunkaddr1079 = getelementptr i8, ptr %sunkaddr1078, i64 56
  %.691.us.us.2.7 = load double, ptr %sunkaddr1079, align 8
  %.720.us.us.2.7 = load double, ptr %scevgep700, align 8
  %.722.us.us.2.7 = fmul double %arg.h, %.720.us.us.2.7
  %.723.us.us.2.7 = fadd double %.691.us.us.2.7, %.722.us.us.2.7
  %sunkaddr1080 = mul i64 %.632619621.us.us.2, 8
  %sunkaddr1081 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1080
  %sunkaddr1082 = getelementptr i8, ptr %sunkaddr1081, i64 56
  store double %.723.us.us.2.7, ptr %sunkaddr1082, align 8
  %exitcond689.2.not.7 = icmp eq i64 %arg.y.2, %.639.us.us.2.7
  br i1 %exitcond689.2.not.7, label %B13409637.us.us.2, label %B13409633.us.us.2, !llvm.loop !40

B13409637.us.us.2:                                ; preds = %B13409633.us.us.2, %B13409633.us.us.2.prol.loopexit, %vec.epilog.middle.block408, %middle.block392, %B13409637.endif.endif.us.us.1
  call void @numba_gil_ensure(ptr nonnull %.854)
  %.857.us.us.2 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.17)
  %.858.us.us.2 = call ptr @PyObject_GetAttrString(ptr %.857.us.us.2, ptr nonnull @.const._get_wrapper_address.18)
  call void @Py_DecRef(ptr %.857.us.us.2)
  %.866.us.us.2 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.19, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.20)
  %.867.us.us.2 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.858.us.us.2, ptr %arg.f.1, ptr %.866.us.us.2, ptr null)
  %.868.us.us.2 = icmp eq ptr %.867.us.us.2, null
  br i1 %.868.us.us.2, label %B13409637.if.if.if, label %B13409637.if.if.endif.us.us.2, !prof !0

B13409637.if.if.endif.us.us.2:                    ; preds = %B13409637.us.us.2
  %.806.us.us.2.idx = mul i64 %arg.K.5.1, 24
  %.806.us.us.2 = getelementptr i8, ptr %arg.K.4, i64 %.806.us.us.2.idx
  %.834.fca.4.insert.us.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us.us.2, 4
  %.834.fca.5.0.insert.us.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us.us.2, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us.us.2, i64 %arg.K.6.1, 6, 0
  %.875.us.us.2 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.867.us.us.2)
  call void @Py_DecRef(ptr nonnull %.867.us.us.2)
  call void @numba_gil_release(ptr nonnull %.854)
  %.885.us.us.2 = call double %.875.us.us.2({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us.us.2)
  %.10.i3 = fcmp olt double %.885.us.us.2, %.11.i2
  %.11.i4 = select i1 %.10.i3, double %.885.us.us.2, double %.11.i2
  br label %B13409639.endif

B13409633.us.us:                                  ; preds = %B13409633.us.us.preheader27, %B13409633.us.us
  %.632619621.us.us = phi i64 [ %.639.us.us.7, %B13409633.us.us ], [ %.632619621.us.us.unr, %B13409633.us.us.preheader27 ]
  %sunkaddr1083 = mul i64 %.632619621.us.us, 8
  %sunkaddr1084 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1083
  %.691.us.us = load double, ptr %sunkaddr1084, align 8
  %sunkaddr1085 = mul i64 %.632619621.us.us, 8
  %sunkaddr1086 = getelementptr i8, ptr %.172, i64 %sunkaddr1085
  %.720.us.us = load double, ptr %sunkaddr1086, align 8
  %.722.us.us = fmul double %.524.us.us, %.720.us.us
  %.723.us.us = fadd double %.691.us.us, %.722.us.us
  %sunkaddr1087 = mul i64 %.632619621.us.us, 8
  %sunkaddr1088 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1087
  store double %.723.us.us, ptr %sunkaddr1088, align 8
  %sunkaddr1089 = mul i64 %.632619621.us.us, 8
  %sunkaddr1090 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1089
  %sunkaddr1091 = getelementptr i8, ptr %sunkaddr1090, i64 8
  %.691.us.us.1539 = load double, ptr %sunkaddr1091, align 8
  %sunkaddr1092 = mul i64 %.632619621.us.us, 8
  %sunkaddr1093 = getelementptr i8, ptr %.172, i64 %sunkaddr1092
  %sunkaddr1094 = getelementptr i8, ptr %sunkaddr1093, i64 8
  %.720.us.us.1541 = load double, ptr %sunkaddr1094, align 8
  %.722.us.us.1542 = fmul double %.524.us.us, %.720.us.us.1541
  %.723.us.us.1543 = fadd double %.691.us.us.1539, %.722.us.us.1542
  %sunkaddr1095 = mul i64 %.632619621.us.us, 8
  %sunkaddr1096 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1095
  %sunkaddr1097 = getelementptr i8, ptr %sunkaddr1096, i64 8
  store double %.723.us.us.1543, ptr %sunkaddr1097, align 8
  %sunkaddr1098 = mul i64 %.632619621.us.us, 8
  %sunkaddr1099 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1098
  %sunkaddr1100 = getelementptr i8, ptr %sunkaddr1099, i64 16
  %.691.us.us.2549 = load double, ptr %sunkaddr1100, align 8
  %sunkaddr1101 = mul i64 %.632619621.us.us, 8
  %sunkaddr1102 = getelementptr i8, ptr %.172, i64 %sunkaddr1101
  %sunkaddr1103 = getelementptr i8, ptr %sunkaddr1102, i64 16
  %.720.us.us.2551 = load double, ptr %sunkaddr1103, align 8
  %.722.us.us.2552 = fmul double %.524.us.us, %.720.us.us.2551
  %.723.us.us.2553 = fadd double %.691.us.us.2549, %.722.us.us.2552
  %sunkaddr1104 = mul i64 %.632619621.us.us, 8
  %sunkaddr1105 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1104
  %sunkaddr1106 = getelementptr i8, ptr %sunkaddr1105, i64 16
  store double %.723.us.us.2553, ptr %sunkaddr1106, align 8
  %sunkaddr1107 = mul i64 %.632619621.us.us, 8
  %sunkaddr1108 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1107
  %sunkaddr1109 = getelementptr i8, ptr %sunkaddr1108, i64 24
  %.691.us.us.3 = load double, ptr %sunkaddr1109, align 8
  %sunkaddr1110 = mul i64 %.632619621.us.us, 8
  %sunkaddr1111 = getelementptr i8, ptr %.172, i64 %sunkaddr1110
  %sunkaddr1112 = getelementptr i8, ptr %sunkaddr1111, i64 24
  %.720.us.us.3 = load double, ptr %sunkaddr1112, align 8
  %.722.us.us.3 = fmul double %.524.us.us, %.720.us.us.3
  %.723.us.us.3 = fadd double %.691.us.us.3, %.722.us.us.3
  %sunkaddr1113 = mul i64 %.632619621.us.us, 8
  %sunkaddr1114 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1113
  %sunkaddr1115 = getelementptr i8, ptr %sunkaddr1114, i64 24
  store double %.723.us.us.3, ptr %sunkaddr1115, align 8
  %sunkaddr1116 = mul i64 %.632619621.us.us, 8
  %sunkaddr1117 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1116
  %sunkaddr1118 = getelementptr i8, ptr %sunkaddr1117, i64 32
  %.691.us.us.4 = load double, ptr %sunkaddr1118, align 8
  %sunkaddr1119 = mul i64 %.632619621.us.us, 8
  %sunkaddr1120 = getelementptr i8, ptr %.172, i64 %sunkaddr1119
  %sunkaddr1121 = getelementptr i8, ptr %sunkaddr1120, i64 32
  %.720.us.us.4 = load double, ptr %sunkaddr1121, align 8
  %.722.us.us.4 = fmul double %.524.us.us, %.720.us.us.4
  %.723.us.us.4 = fadd double %.691.us.us.4, %.722.us.us.4
  %sunkaddr1122 = mul i64 %.632619621.us.us, 8
  %sunkaddr1123 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1122
  %sunkaddr1124 = getelementptr i8, ptr %sunkaddr1123, i64 32
  store double %.723.us.us.4, ptr %sunkaddr1124, align 8
  %sunkaddr1125 = mul i64 %.632619621.us.us, 8
  %sunkaddr1126 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1125
  %sunkaddr1127 = getelementptr i8, ptr %sunkaddr1126, i64 40
  %.691.us.us.5 = load double, ptr %sunkaddr1127, align 8
  %sunkaddr1128 = mul i64 %.632619621.us.us, 8
  %sunkaddr1129 = getelementptr i8, ptr %.172, i64 %sunkaddr1128
  %sunkaddr1130 = getelementptr i8, ptr %sunkaddr1129, i64 40
  %.720.us.us.5 = load double, ptr %sunkaddr1130, align 8
  %.722.us.us.5 = fmul double %.524.us.us, %.720.us.us.5
  %.723.us.us.5 = fadd double %.691.us.us.5, %.722.us.us.5
  %sunkaddr1131 = mul i64 %.632619621.us.us, 8
  %sunkaddr1132 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1131
  %sunkaddr1133 = getelementptr i8, ptr %sunkaddr1132, i64 40
  store double %.723.us.us.5, ptr %sunkaddr1133, align 8
  %sunkaddr1134 = mul i64 %.632619621.us.us, 8
  %sunkaddr1135 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1134
  %sunkaddr1136 = getelementptr i8, ptr %sunkaddr1135, i64 48
  %.691.us.us.6 = load double, ptr %sunkaddr1136, align 8
  %sunkaddr1137 = mul i64 %.632619621.us.us, 8
  %sunkaddr1138 = getelementptr i8, ptr %.172, i64 %sunkaddr1137
  %sunkaddr1139 = getelementptr i8, ptr %sunkaddr1138, i64 48
  %.720.us.us.6 = load double, ptr %sunkaddr1139, align 8
  %.722.us.us.6 = fmul double %.524.us.us, %.720.us.us.6
  %.723.us.us.6 = fadd double %.691.us.us.6, %.722.us.us.6
  %sunkaddr1140 = mul i64 %.632619621.us.us, 8
  %sunkaddr1141 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1140
  %sunkaddr1142 = getelementptr i8, ptr %sunkaddr1141, i64 48
  store double %.723.us.us.6, ptr %sunkaddr1142, align 8
  %.639.us.us.7 = add nuw nsw i64 %.632619621.us.us, 8
  %sunkaddr1143 = mul i64 %.632619621.us.us, 8
  %sunkaddr1144 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1143
  %sunkaddr1145 = getelementptr i8, ptr %sunkaddr1144, i64 56
  %.691.us.us.7 = load double, ptr %sunkaddr1145, align 8
  %sunkaddr1146 = mul i64 %.632619621.us.us, 8
  %sunkaddr1147 = getelementptr i8, ptr %.172, i64 %sunkaddr1146
  %sunkaddr1148 = getelementptr i8, ptr %sunkaddr1147, i64 56
  %.720.us.us.7 = load double, ptr %sunkaddr1148, align 8
  %.722.us.us.7 = fmul double %.524.us.us, %.720.us.us.7
  %.723.us.us.7 = fadd double %.691.us.us.7, %.722.us.us.7
  %sunkaddr1149 = mul i64 %.632619621.us.us, 8
  %sunkaddr1150 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1149
  %sunkaddr1151 = getelementptr i8, ptr %sunkaddr1150, i64 56
  store double %.723.us.us.7, ptr %sunkaddr1151, align 8
  %exitcond689.not.7 = icmp eq i64 %arg.y.2, %.639.us.us.7
  br i1 %exitcond689.not.7, label %B13409637.us.us, label %B13409633.us.us, !llvm.loop !41

B13409637.endif.endif.us:                         ; preds = %B13409633.us, %B13409633.us.prol.loopexit, %vec.epilog.middle.block178, %middle.block162, %B178.us.preheader
  %168 = icmp slt i64 %arg.y.2, 1
  %.806.us = getelementptr double, ptr %arg.K.4, i64 %arg.K.5.1
  %.834.fca.4.insert.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us, 4
  %.834.fca.5.0.insert.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us, i64 %arg.K.6.1, 6, 0
  %.885.us = call double %arg.f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us)
  %.10.i5 = fcmp olt double %.885.us, %.278.0
  %.11.i6 = select i1 %.10.i5, double %.885.us, double %.278.0
  br i1 %168, label %B13409637.endif.endif.us.1, label %iter.check189

iter.check189:                                    ; preds = %B13409637.endif.endif.us
  %169 = getelementptr double, ptr %.172, i64 %arg.y.2
  %min.iters.check187 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check187, label %B13409633.us.1.preheader, label %vector.memcheck181

vector.memcheck181:                               ; preds = %iter.check189
  %170 = ptrtoint ptr %.172 to i64
  %171 = ptrtoint ptr %arg.ytmp.4 to i64
  %172 = ptrtoint ptr %arg.y.4 to i64
  %173 = sub i64 %171, %172
  %diff.check184 = icmp ult i64 %173, 256
  %174 = shl i64 %arg.y.2, 3
  %175 = add i64 %174, %170
  %176 = sub i64 %171, %175
  %diff.check185 = icmp ult i64 %176, 256
  %conflict.rdx186 = or i1 %diff.check184, %diff.check185
  br i1 %conflict.rdx186, label %B13409633.us.1.preheader, label %vector.main.loop.iter.check191

vector.main.loop.iter.check191:                   ; preds = %vector.memcheck181
  %const758 = bitcast i64 9223372036854775776 to i64
  %min.iters.check190 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check190, label %vec.epilog.ph214, label %vector.ph192

vector.ph192:                                     ; preds = %vector.main.loop.iter.check191
  %n.vec194 = and i64 %arg.y.2, %const758
  %broadcast.splatinsert195 = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat196 = shufflevector <8 x double> %broadcast.splatinsert195, <8 x double> poison, <8 x i32> zeroinitializer
  %177 = getelementptr i8, ptr %.172, i64 %174
  %scevgep1056 = getelementptr i8, ptr %177, i64 192
  br label %vector.body197

vector.body197:                                   ; preds = %vector.body197, %vector.ph192
  %index198 = phi i64 [ 0, %vector.ph192 ], [ %index.next207, %vector.body197 ]
  %sunkaddr1152 = mul i64 %index198, 8
  %sunkaddr1153 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1152
  %wide.load199 = load <8 x double>, ptr %sunkaddr1153, align 8
  %sunkaddr1154 = mul i64 %index198, 8
  %sunkaddr1155 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1154
  %sunkaddr1156 = getelementptr i8, ptr %sunkaddr1155, i64 64
  %wide.load200 = load <8 x double>, ptr %sunkaddr1156, align 8
  %sunkaddr1157 = mul i64 %index198, 8
  %sunkaddr1158 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1157
  %sunkaddr1159 = getelementptr i8, ptr %sunkaddr1158, i64 128
  %wide.load201 = load <8 x double>, ptr %sunkaddr1159, align 8
  %sunkaddr1160 = mul i64 %index198, 8
  %sunkaddr1161 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1160
  %sunkaddr1162 = getelementptr i8, ptr %sunkaddr1161, i64 192
  %wide.load202 = load <8 x double>, ptr %sunkaddr1162, align 8
  %178 = shl i64 %index198, 3
  %scevgep435 = getelementptr i8, ptr %scevgep1056, i64 %178
  %scevgep438 = getelementptr i8, ptr %scevgep435, i64 -192
  %scevgep437 = getelementptr i8, ptr %scevgep435, i64 -128
  %scevgep436 = getelementptr i8, ptr %scevgep435, i64 -64
  %wide.load203 = load <8 x double>, ptr %scevgep438, align 8
  %wide.load204 = load <8 x double>, ptr %scevgep437, align 8
  %wide.load205 = load <8 x double>, ptr %scevgep436, align 8
  %wide.load206 = load <8 x double>, ptr %scevgep435, align 8
  %179 = fmul <8 x double> %broadcast.splat196, %wide.load203
  %180 = fmul <8 x double> %broadcast.splat196, %wide.load204
  %181 = fmul <8 x double> %broadcast.splat196, %wide.load205
  %182 = fmul <8 x double> %broadcast.splat196, %wide.load206
  %183 = fadd <8 x double> %wide.load199, %179
  %184 = fadd <8 x double> %wide.load200, %180
  %185 = fadd <8 x double> %wide.load201, %181
  %186 = fadd <8 x double> %wide.load202, %182
  %sunkaddr1163 = mul i64 %index198, 8
  %sunkaddr1164 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1163
  store <8 x double> %183, ptr %sunkaddr1164, align 8
  %sunkaddr1165 = mul i64 %index198, 8
  %sunkaddr1166 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1165
  %sunkaddr1167 = getelementptr i8, ptr %sunkaddr1166, i64 64
  store <8 x double> %184, ptr %sunkaddr1167, align 8
  %sunkaddr1168 = mul i64 %index198, 8
  %sunkaddr1169 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1168
  %sunkaddr1170 = getelementptr i8, ptr %sunkaddr1169, i64 128
  store <8 x double> %185, ptr %sunkaddr1170, align 8
  %sunkaddr1171 = mul i64 %index198, 8
  %sunkaddr1172 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1171
  %sunkaddr1173 = getelementptr i8, ptr %sunkaddr1172, i64 192
  store <8 x double> %186, ptr %sunkaddr1173, align 8
  %index.next207 = add nuw nsw i64 %index198, 32
  %187 = icmp eq i64 %n.vec194, %index.next207
  br i1 %187, label %middle.block208, label %vector.body197, !llvm.loop !42

middle.block208:                                  ; preds = %vector.body197
  %cmp.n209 = icmp eq i64 %arg.y.2, %n.vec194
  br i1 %cmp.n209, label %B13409637.endif.endif.us.1, label %vec.epilog.iter.check212

vec.epilog.iter.check212:                         ; preds = %middle.block208
  %188 = and i64 %arg.y.2, 28
  %min.epilog.iters.check213 = icmp eq i64 %188, 0
  br i1 %min.epilog.iters.check213, label %B13409633.us.1.preheader, label %vec.epilog.ph214, !prof !9

vec.epilog.ph214:                                 ; preds = %vec.epilog.iter.check212, %vector.main.loop.iter.check191
  %vec.epilog.resume.val210 = phi i64 [ %n.vec194, %vec.epilog.iter.check212 ], [ 0, %vector.main.loop.iter.check191 ]
  %const_mat759 = add i64 %const758, 28
  %n.vec216 = and i64 %arg.y.2, %const_mat759
  %broadcast.splatinsert217 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat218 = shufflevector <4 x double> %broadcast.splatinsert217, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body219

vec.epilog.vector.body219:                        ; preds = %vec.epilog.vector.body219, %vec.epilog.ph214
  %index220 = phi i64 [ %vec.epilog.resume.val210, %vec.epilog.ph214 ], [ %index.next223, %vec.epilog.vector.body219 ]
  %189 = shl i64 %index220, 3
  %scevgep1047 = getelementptr i8, ptr %arg.y.4, i64 %189
  %wide.load221 = load <4 x double>, ptr %scevgep1047, align 8
  %scevgep1046 = getelementptr i8, ptr %169, i64 %189
  %wide.load222 = load <4 x double>, ptr %scevgep1046, align 8
  %190 = fmul <4 x double> %broadcast.splat218, %wide.load222
  %191 = fadd <4 x double> %wide.load221, %190
  %192 = shl i64 %index220, 3
  %scevgep426 = getelementptr i8, ptr %arg.ytmp.4, i64 %192
  store <4 x double> %191, ptr %scevgep426, align 8
  %index.next223 = add nuw i64 %index220, 4
  %193 = icmp eq i64 %n.vec216, %index.next223
  br i1 %193, label %vec.epilog.middle.block224, label %vec.epilog.vector.body219, !llvm.loop !43

vec.epilog.middle.block224:                       ; preds = %vec.epilog.vector.body219
  %cmp.n225 = icmp eq i64 %arg.y.2, %n.vec216
  br i1 %cmp.n225, label %B13409637.endif.endif.us.1, label %B13409633.us.1.preheader

B13409633.us.1.preheader:                         ; preds = %vec.epilog.middle.block224, %vec.epilog.iter.check212, %vector.memcheck181, %iter.check189
  %.632619621.us.1.ph = phi i64 [ 0, %iter.check189 ], [ 0, %vector.memcheck181 ], [ %n.vec194, %vec.epilog.iter.check212 ], [ %n.vec216, %vec.epilog.middle.block224 ]
  %194 = sub nsw i64 %arg.y.2, %.632619621.us.1.ph
  %xtraiter527 = and i64 %194, 7
  %lcmp.mod528.not = icmp eq i64 %xtraiter527, 0
  br i1 %lcmp.mod528.not, label %B13409633.us.1.prol.loopexit, label %B13409633.us.1.prol.preheader

B13409633.us.1.prol.preheader:                    ; preds = %B13409633.us.1.preheader
  br label %B13409633.us.1.prol

B13409633.us.1.prol:                              ; preds = %B13409633.us.1.prol.preheader, %B13409633.us.1.prol
  %lsr.iv1043 = phi i64 [ %lsr.iv.next1044, %B13409633.us.1.prol ], [ %xtraiter527, %B13409633.us.1.prol.preheader ]
  %.632619621.us.1.prol = phi i64 [ %.639.us.1.prol, %B13409633.us.1.prol ], [ %.632619621.us.1.ph, %B13409633.us.1.prol.preheader ]
  %.639.us.1.prol = add nuw i64 %.632619621.us.1.prol, 1
  %195 = shl i64 %.632619621.us.1.prol, 3
  %scevgep1042 = getelementptr i8, ptr %arg.y.4, i64 %195
  %.691.us.1.prol = load double, ptr %scevgep1042, align 8
  %scevgep1041 = getelementptr i8, ptr %169, i64 %195
  %.720.us.1.prol = load double, ptr %scevgep1041, align 8
  %.722.us.1.prol = fmul double %.524.us.us, %.720.us.1.prol
  %.723.us.1.prol = fadd double %.691.us.1.prol, %.722.us.1.prol
  %196 = shl i64 %.632619621.us.1.prol, 3
  %scevgep425 = getelementptr i8, ptr %arg.ytmp.4, i64 %196
  store double %.723.us.1.prol, ptr %scevgep425, align 8
  %lsr.iv.next1044 = add nsw i64 %lsr.iv1043, -1
  %prol.iter529.cmp.not = icmp eq i64 %lsr.iv.next1044, 0
  br i1 %prol.iter529.cmp.not, label %B13409633.us.1.prol.loopexit, label %B13409633.us.1.prol, !llvm.loop !44

B13409633.us.1.prol.loopexit:                     ; preds = %B13409633.us.1.prol, %B13409633.us.1.preheader
  %.632619621.us.1.unr = phi i64 [ %.632619621.us.1.ph, %B13409633.us.1.preheader ], [ %.639.us.1.prol, %B13409633.us.1.prol ]
  %197 = sub nsw i64 %.632619621.us.1.ph, %arg.y.2
  %198 = icmp ugt i64 %197, -8
  br i1 %198, label %B13409637.endif.endif.us.1, label %B13409633.us.1.preheader570

B13409633.us.1.preheader570:                      ; preds = %B13409633.us.1.prol.loopexit
  %199 = shl i64 %arg.y.2, 3
  %200 = getelementptr i8, ptr %.172, i64 %199
  %scevgep1008 = getelementptr i8, ptr %200, i64 56
  br label %B13409633.us.1

B13409633.us.1:                                   ; preds = %B13409633.us.1, %B13409633.us.1.preheader570
  %.632619621.us.1 = phi i64 [ %.639.us.1.7, %B13409633.us.1 ], [ %.632619621.us.1.unr, %B13409633.us.1.preheader570 ]
  %sunkaddr1805 = shl i64 %.632619621.us.1, 3
  %sunkaddr1174 = mul i64 %.632619621.us.1, 8
  %sunkaddr1175 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1174
  %.691.us.1 = load double, ptr %sunkaddr1175, align 8
  %scevgep1020 = getelementptr i8, ptr %scevgep1008, i64 %sunkaddr1805
  %scevgep1021 = getelementptr i8, ptr %scevgep1020, i64 -56
  %.720.us.1 = load double, ptr %scevgep1021, align 8
  %.722.us.1 = fmul double %.524.us.us, %.720.us.1
  %.723.us.1 = fadd double %.691.us.1, %.722.us.1
  %sunkaddr1176 = mul i64 %.632619621.us.1, 8
  %sunkaddr1177 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1176
  store double %.723.us.1, ptr %sunkaddr1177, align 8
  %sunkaddr1178 = mul i64 %.632619621.us.1, 8
  %sunkaddr1179 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1178
  %sunkaddr1180 = getelementptr i8, ptr %sunkaddr1179, i64 8
  %.691.us.1.1 = load double, ptr %sunkaddr1180, align 8
  %201 = shl i64 %.632619621.us.1, 3
  %scevgep407 = getelementptr i8, ptr %scevgep1008, i64 %201
  %scevgep408 = getelementptr i8, ptr %scevgep407, i64 -48
  %.720.us.1.1 = load double, ptr %scevgep408, align 8
  %.722.us.1.1 = fmul double %.524.us.us, %.720.us.1.1
  %.723.us.1.1 = fadd double %.691.us.1.1, %.722.us.1.1
  %sunkaddr1181 = mul i64 %.632619621.us.1, 8
  %sunkaddr1182 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1181
  %sunkaddr1183 = getelementptr i8, ptr %sunkaddr1182, i64 8
  store double %.723.us.1.1, ptr %sunkaddr1183, align 8
  %sunkaddr1184 = mul i64 %.632619621.us.1, 8
  %sunkaddr1185 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1184
  %sunkaddr1186 = getelementptr i8, ptr %sunkaddr1185, i64 16
  %.691.us.1.2 = load double, ptr %sunkaddr1186, align 8
  %202 = shl i64 %.632619621.us.1, 3
  %scevgep405 = getelementptr i8, ptr %scevgep1008, i64 %202
  %scevgep406 = getelementptr i8, ptr %scevgep405, i64 -40
  %.720.us.1.2 = load double, ptr %scevgep406, align 8
  %.722.us.1.2 = fmul double %.524.us.us, %.720.us.1.2
  %.723.us.1.2 = fadd double %.691.us.1.2, %.722.us.1.2
  %sunkaddr1187 = mul i64 %.632619621.us.1, 8
  %sunkaddr1188 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1187
  %sunkaddr1189 = getelementptr i8, ptr %sunkaddr1188, i64 16
  store double %.723.us.1.2, ptr %sunkaddr1189, align 8
  %sunkaddr1190 = mul i64 %.632619621.us.1, 8
  %sunkaddr1191 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1190
  %sunkaddr1192 = getelementptr i8, ptr %sunkaddr1191, i64 24
  %.691.us.1.3 = load double, ptr %sunkaddr1192, align 8
  %203 = shl i64 %.632619621.us.1, 3
  %scevgep403 = getelementptr i8, ptr %scevgep1008, i64 %203
  %scevgep404 = getelementptr i8, ptr %scevgep403, i64 -32
  %.720.us.1.3 = load double, ptr %scevgep404, align 8
  %.722.us.1.3 = fmul double %.524.us.us, %.720.us.1.3
  %.723.us.1.3 = fadd double %.691.us.1.3, %.722.us.1.3
  %sunkaddr1193 = mul i64 %.632619621.us.1, 8
  %sunkaddr1194 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1193
  %sunkaddr1195 = getelementptr i8, ptr %sunkaddr1194, i64 24
  store double %.723.us.1.3, ptr %sunkaddr1195, align 8
  %sunkaddr1196 = mul i64 %.632619621.us.1, 8
  %sunkaddr1197 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1196
  %sunkaddr1198 = getelementptr i8, ptr %sunkaddr1197, i64 32
  %.691.us.1.4 = load double, ptr %sunkaddr1198, align 8
  %204 = shl i64 %.632619621.us.1, 3
  %scevgep401 = getelementptr i8, ptr %scevgep1008, i64 %204
  %scevgep402 = getelementptr i8, ptr %scevgep401, i64 -24
  %.720.us.1.4 = load double, ptr %scevgep402, align 8
  %.722.us.1.4 = fmul double %.524.us.us, %.720.us.1.4
  %.723.us.1.4 = fadd double %.691.us.1.4, %.722.us.1.4
  %sunkaddr1199 = mul i64 %.632619621.us.1, 8
  %sunkaddr1200 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1199
  %sunkaddr1201 = getelementptr i8, ptr %sunkaddr1200, i64 32
  store double %.723.us.1.4, ptr %sunkaddr1201, align 8
  %sunkaddr1202 = mul i64 %.632619621.us.1, 8
  %sunkaddr1203 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1202
  %sunkaddr1204 = getelementptr i8, ptr %sunkaddr1203, i64 40
  %.691.us.1.5 = load double, ptr %sunkaddr1204, align 8
  %205 = shl i64 %.632619621.us.1, 3
  %scevgep399 = getelementptr i8, ptr %scevgep1008, i64 %205
  %scevgep400 = getelementptr i8, ptr %scevgep399, i64 -16
  %.720.us.1.5 = load double, ptr %scevgep400, align 8
  %.722.us.1.5 = fmul double %.524.us.us, %.720.us.1.5
  %.723.us.1.5 = fadd double %.691.us.1.5, %.722.us.1.5
  %sunkaddr1205 = mul i64 %.632619621.us.1, 8
  %sunkaddr1206 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1205
  %sunkaddr1207 = getelementptr i8, ptr %sunkaddr1206, i64 40
  store double %.723.us.1.5, ptr %sunkaddr1207, align 8
  %sunkaddr1208 = mul i64 %.632619621.us.1, 8
  %sunkaddr1209 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1208
  %sunkaddr1210 = getelementptr i8, ptr %sunkaddr1209, i64 48
  %.691.us.1.6 = load double, ptr %sunkaddr1210, align 8
  %206 = shl i64 %.632619621.us.1, 3
  %scevgep397 = getelementptr i8, ptr %scevgep1008, i64 %206
  %scevgep398 = getelementptr i8, ptr %scevgep397, i64 -8
  %.720.us.1.6 = load double, ptr %scevgep398, align 8
  %.722.us.1.6 = fmul double %.524.us.us, %.720.us.1.6
  %.723.us.1.6 = fadd double %.691.us.1.6, %.722.us.1.6
  %sunkaddr1211 = mul i64 %.632619621.us.1, 8
  %sunkaddr1212 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1211
  %sunkaddr1213 = getelementptr i8, ptr %sunkaddr1212, i64 48
  store double %.723.us.1.6, ptr %sunkaddr1213, align 8
  %.639.us.1.7 = add nuw nsw i64 %.632619621.us.1, 8
  %sunkaddr1214 = mul i64 %.632619621.us.1, 8
  %sunkaddr1215 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1214
  %sunkaddr1216 = getelementptr i8, ptr %sunkaddr1215, i64 56
  %.691.us.1.7 = load double, ptr %sunkaddr1216, align 8
  %.720.us.1.7 = load double, ptr %scevgep1020, align 8
  %.722.us.1.7 = fmul double %.524.us.us, %.720.us.1.7
  %.723.us.1.7 = fadd double %.691.us.1.7, %.722.us.1.7
  %sunkaddr1217 = mul i64 %.632619621.us.1, 8
  %sunkaddr1218 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1217
  %sunkaddr1219 = getelementptr i8, ptr %sunkaddr1218, i64 56
  store double %.723.us.1.7, ptr %sunkaddr1219, align 8
  %exitcond688.1.not.7 = icmp eq i64 %arg.y.2, %.639.us.1.7
  br i1 %exitcond688.1.not.7, label %B13409637.endif.endif.us.1, label %B13409633.us.1, !llvm.loop !45

B13409637.endif.endif.us.1:                       ; preds = %B13409633.us.1, %B13409633.us.1.prol.loopexit, %vec.epilog.middle.block224, %middle.block208, %B13409637.endif.endif.us
  %207 = icmp slt i64 %arg.y.2, 1
  %.806.us.1.idx = shl i64 %arg.K.5.1, 4
  %.806.us.1 = getelementptr i8, ptr %arg.K.4, i64 %.806.us.1.idx
  %.834.fca.4.insert.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us.1, 4
  %.834.fca.5.0.insert.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us.1, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us.1 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us.1, i64 %arg.K.6.1, 6, 0
  %.885.us.1 = call double %arg.f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us.1)
  %.10.i7 = fcmp olt double %.885.us.1, %.11.i6
  %.11.i8 = select i1 %.10.i7, double %.885.us.1, double %.11.i6
  br i1 %207, label %B13409637.us.2, label %iter.check235

iter.check235:                                    ; preds = %B13409637.endif.endif.us.1
  %.idx692 = shl i64 %arg.y.2, 4
  %208 = getelementptr i8, ptr %.172, i64 %.idx692
  %min.iters.check233 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check233, label %B13409633.us.2.preheader, label %vector.memcheck227

vector.memcheck227:                               ; preds = %iter.check235
  %209 = ptrtoint ptr %.172 to i64
  %210 = ptrtoint ptr %arg.ytmp.4 to i64
  %211 = ptrtoint ptr %arg.y.4 to i64
  %212 = sub i64 %210, %211
  %diff.check230 = icmp ult i64 %212, 256
  %213 = add i64 %.idx692, %209
  %214 = sub i64 %210, %213
  %diff.check231 = icmp ult i64 %214, 256
  %conflict.rdx232 = or i1 %diff.check230, %diff.check231
  br i1 %conflict.rdx232, label %B13409633.us.2.preheader, label %vector.main.loop.iter.check237

vector.main.loop.iter.check237:                   ; preds = %vector.memcheck227
  %const760 = bitcast i64 9223372036854775776 to i64
  %min.iters.check236 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check236, label %vec.epilog.ph260, label %vector.ph238

vector.ph238:                                     ; preds = %vector.main.loop.iter.check237
  %n.vec240 = and i64 %arg.y.2, %const760
  %broadcast.splatinsert241 = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat242 = shufflevector <8 x double> %broadcast.splatinsert241, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body243

vector.body243:                                   ; preds = %vector.body243, %vector.ph238
  %index244 = phi i64 [ 0, %vector.ph238 ], [ %index.next253, %vector.body243 ]
  %sunkaddr1220 = mul i64 %index244, 8
  %sunkaddr1221 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1220
  %wide.load245 = load <8 x double>, ptr %sunkaddr1221, align 8
  %sunkaddr1222 = mul i64 %index244, 8
  %sunkaddr1223 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1222
  %sunkaddr1224 = getelementptr i8, ptr %sunkaddr1223, i64 64
  %wide.load246 = load <8 x double>, ptr %sunkaddr1224, align 8
  %sunkaddr1225 = mul i64 %index244, 8
  %sunkaddr1226 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1225
  %sunkaddr1227 = getelementptr i8, ptr %sunkaddr1226, i64 128
  %wide.load247 = load <8 x double>, ptr %sunkaddr1227, align 8
  %sunkaddr1228 = mul i64 %index244, 8
  %sunkaddr1229 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1228
  %sunkaddr1230 = getelementptr i8, ptr %sunkaddr1229, i64 192
  %wide.load248 = load <8 x double>, ptr %sunkaddr1230, align 8
  %sunkaddr1231 = mul i64 %index244, 8
  %sunkaddr1232 = getelementptr i8, ptr %208, i64 %sunkaddr1231
  %wide.load249 = load <8 x double>, ptr %sunkaddr1232, align 8
  %sunkaddr1233 = mul i64 %index244, 8
  %sunkaddr1234 = getelementptr i8, ptr %208, i64 %sunkaddr1233
  %sunkaddr1235 = getelementptr i8, ptr %sunkaddr1234, i64 64
  %wide.load250 = load <8 x double>, ptr %sunkaddr1235, align 8
  %sunkaddr1236 = mul i64 %index244, 8
  %sunkaddr1237 = getelementptr i8, ptr %208, i64 %sunkaddr1236
  %sunkaddr1238 = getelementptr i8, ptr %sunkaddr1237, i64 128
  %wide.load251 = load <8 x double>, ptr %sunkaddr1238, align 8
  %sunkaddr1239 = mul i64 %index244, 8
  %sunkaddr1240 = getelementptr i8, ptr %208, i64 %sunkaddr1239
  %sunkaddr1241 = getelementptr i8, ptr %sunkaddr1240, i64 192
  %wide.load252 = load <8 x double>, ptr %sunkaddr1241, align 8
  %215 = fmul <8 x double> %broadcast.splat242, %wide.load249
  %216 = fmul <8 x double> %broadcast.splat242, %wide.load250
  %217 = fmul <8 x double> %broadcast.splat242, %wide.load251
  %218 = fmul <8 x double> %broadcast.splat242, %wide.load252
  %219 = fadd <8 x double> %wide.load245, %215
  %220 = fadd <8 x double> %wide.load246, %216
  %221 = fadd <8 x double> %wide.load247, %217
  %222 = fadd <8 x double> %wide.load248, %218
  %sunkaddr1242 = mul i64 %index244, 8
  %sunkaddr1243 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1242
  store <8 x double> %219, ptr %sunkaddr1243, align 8
  %sunkaddr1244 = mul i64 %index244, 8
  %sunkaddr1245 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1244
  %sunkaddr1246 = getelementptr i8, ptr %sunkaddr1245, i64 64
  store <8 x double> %220, ptr %sunkaddr1246, align 8
  %sunkaddr1247 = mul i64 %index244, 8
  %sunkaddr1248 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1247
  %sunkaddr1249 = getelementptr i8, ptr %sunkaddr1248, i64 128
  store <8 x double> %221, ptr %sunkaddr1249, align 8
  %sunkaddr1250 = mul i64 %index244, 8
  %sunkaddr1251 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1250
  %sunkaddr1252 = getelementptr i8, ptr %sunkaddr1251, i64 192
  store <8 x double> %222, ptr %sunkaddr1252, align 8
  %index.next253 = add nuw nsw i64 %index244, 32
  %223 = icmp eq i64 %n.vec240, %index.next253
  br i1 %223, label %middle.block254, label %vector.body243, !llvm.loop !46

middle.block254:                                  ; preds = %vector.body243
  %cmp.n255 = icmp eq i64 %arg.y.2, %n.vec240
  br i1 %cmp.n255, label %B13409637.us.2, label %vec.epilog.iter.check258

vec.epilog.iter.check258:                         ; preds = %middle.block254
  %224 = and i64 %arg.y.2, 28
  %min.epilog.iters.check259 = icmp eq i64 %224, 0
  br i1 %min.epilog.iters.check259, label %B13409633.us.2.preheader, label %vec.epilog.ph260, !prof !9

vec.epilog.ph260:                                 ; preds = %vec.epilog.iter.check258, %vector.main.loop.iter.check237
  %vec.epilog.resume.val256 = phi i64 [ %n.vec240, %vec.epilog.iter.check258 ], [ 0, %vector.main.loop.iter.check237 ]
  %const_mat761 = add i64 %const760, 28
  %n.vec262 = and i64 %arg.y.2, %const_mat761
  %broadcast.splatinsert263 = insertelement <4 x double> poison, double %arg.h, i64 0
  %broadcast.splat264 = shufflevector <4 x double> %broadcast.splatinsert263, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body265

vec.epilog.vector.body265:                        ; preds = %vec.epilog.vector.body265, %vec.epilog.ph260
  %index266 = phi i64 [ %vec.epilog.resume.val256, %vec.epilog.ph260 ], [ %index.next269, %vec.epilog.vector.body265 ]
  %225 = shl i64 %index266, 3
  %scevgep967 = getelementptr i8, ptr %arg.y.4, i64 %225
  %wide.load267 = load <4 x double>, ptr %scevgep967, align 8
  %scevgep966 = getelementptr i8, ptr %208, i64 %225
  %wide.load268 = load <4 x double>, ptr %scevgep966, align 8
  %226 = fmul <4 x double> %broadcast.splat264, %wide.load268
  %227 = fadd <4 x double> %wide.load267, %226
  %228 = shl i64 %index266, 3
  %scevgep360 = getelementptr i8, ptr %arg.ytmp.4, i64 %228
  store <4 x double> %227, ptr %scevgep360, align 8
  %index.next269 = add nuw i64 %index266, 4
  %229 = icmp eq i64 %n.vec262, %index.next269
  br i1 %229, label %vec.epilog.middle.block270, label %vec.epilog.vector.body265, !llvm.loop !47

vec.epilog.middle.block270:                       ; preds = %vec.epilog.vector.body265
  %cmp.n271 = icmp eq i64 %arg.y.2, %n.vec262
  br i1 %cmp.n271, label %B13409637.us.2, label %B13409633.us.2.preheader

B13409633.us.2.preheader:                         ; preds = %vec.epilog.middle.block270, %vec.epilog.iter.check258, %vector.memcheck227, %iter.check235
  %.632619621.us.2.ph = phi i64 [ 0, %iter.check235 ], [ 0, %vector.memcheck227 ], [ %n.vec240, %vec.epilog.iter.check258 ], [ %n.vec262, %vec.epilog.middle.block270 ]
  %230 = sub nsw i64 %arg.y.2, %.632619621.us.2.ph
  %xtraiter530 = and i64 %230, 7
  %lcmp.mod531.not = icmp eq i64 %xtraiter530, 0
  br i1 %lcmp.mod531.not, label %B13409633.us.2.prol.loopexit, label %B13409633.us.2.prol.preheader

B13409633.us.2.prol.preheader:                    ; preds = %B13409633.us.2.preheader
  br label %B13409633.us.2.prol

B13409633.us.2.prol:                              ; preds = %B13409633.us.2.prol.preheader, %B13409633.us.2.prol
  %lsr.iv963 = phi i64 [ %lsr.iv.next964, %B13409633.us.2.prol ], [ %xtraiter530, %B13409633.us.2.prol.preheader ]
  %.632619621.us.2.prol = phi i64 [ %.639.us.2.prol, %B13409633.us.2.prol ], [ %.632619621.us.2.ph, %B13409633.us.2.prol.preheader ]
  %.639.us.2.prol = add nuw i64 %.632619621.us.2.prol, 1
  %231 = shl i64 %.632619621.us.2.prol, 3
  %scevgep962 = getelementptr i8, ptr %arg.y.4, i64 %231
  %.691.us.2.prol = load double, ptr %scevgep962, align 8
  %scevgep961 = getelementptr i8, ptr %208, i64 %231
  %.720.us.2.prol = load double, ptr %scevgep961, align 8
  %.722.us.2.prol = fmul double %arg.h, %.720.us.2.prol
  %.723.us.2.prol = fadd double %.691.us.2.prol, %.722.us.2.prol
  %232 = shl i64 %.632619621.us.2.prol, 3
  %scevgep359 = getelementptr i8, ptr %arg.ytmp.4, i64 %232
  store double %.723.us.2.prol, ptr %scevgep359, align 8
  %lsr.iv.next964 = add nsw i64 %lsr.iv963, -1
  %prol.iter532.cmp.not = icmp eq i64 %lsr.iv.next964, 0
  br i1 %prol.iter532.cmp.not, label %B13409633.us.2.prol.loopexit, label %B13409633.us.2.prol, !llvm.loop !48

B13409633.us.2.prol.loopexit:                     ; preds = %B13409633.us.2.prol, %B13409633.us.2.preheader
  %.632619621.us.2.unr = phi i64 [ %.632619621.us.2.ph, %B13409633.us.2.preheader ], [ %.639.us.2.prol, %B13409633.us.2.prol ]
  %233 = sub nsw i64 %.632619621.us.2.ph, %arg.y.2
  %234 = icmp ugt i64 %233, -8
  br i1 %234, label %B13409637.us.2, label %B13409633.us.2.preheader569

B13409633.us.2.preheader569:                      ; preds = %B13409633.us.2.prol.loopexit
  %scevgep928 = getelementptr i8, ptr %208, i64 56
  br label %B13409633.us.2

B13409633.us.2:                                   ; preds = %B13409633.us.2, %B13409633.us.2.preheader569
  %.632619621.us.2 = phi i64 [ %.639.us.2.7, %B13409633.us.2 ], [ %.632619621.us.2.unr, %B13409633.us.2.preheader569 ]
  %sunkaddr1873 = shl i64 %.632619621.us.2, 3
  %sunkaddr1253 = mul i64 %.632619621.us.2, 8
  %sunkaddr1254 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1253
  %.691.us.2 = load double, ptr %sunkaddr1254, align 8
  %scevgep940 = getelementptr i8, ptr %scevgep928, i64 %sunkaddr1873
  %scevgep941 = getelementptr i8, ptr %scevgep940, i64 -56
  %.720.us.2 = load double, ptr %scevgep941, align 8
  %.722.us.2 = fmul double %arg.h, %.720.us.2
  %.723.us.2 = fadd double %.691.us.2, %.722.us.2
  %sunkaddr1255 = mul i64 %.632619621.us.2, 8
  %sunkaddr1256 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1255
  store double %.723.us.2, ptr %sunkaddr1256, align 8
  %sunkaddr1257 = mul i64 %.632619621.us.2, 8
  %sunkaddr1258 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1257
  %sunkaddr1259 = getelementptr i8, ptr %sunkaddr1258, i64 8
  %.691.us.2.1 = load double, ptr %sunkaddr1259, align 8
  %235 = shl i64 %.632619621.us.2, 3
  %scevgep341 = getelementptr i8, ptr %scevgep928, i64 %235
  %scevgep342 = getelementptr i8, ptr %scevgep341, i64 -48
  %.720.us.2.1 = load double, ptr %scevgep342, align 8
  %.722.us.2.1 = fmul double %arg.h, %.720.us.2.1
  %.723.us.2.1 = fadd double %.691.us.2.1, %.722.us.2.1
  %sunkaddr1260 = mul i64 %.632619621.us.2, 8
  %sunkaddr1261 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1260
  %sunkaddr1262 = getelementptr i8, ptr %sunkaddr1261, i64 8
  store double %.723.us.2.1, ptr %sunkaddr1262, align 8
  %sunkaddr1263 = mul i64 %.632619621.us.2, 8
  %sunkaddr1264 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1263
  %sunkaddr1265 = getelementptr i8, ptr %sunkaddr1264, i64 16
  %.691.us.2.2 = load double, ptr %sunkaddr1265, align 8
  %236 = shl i64 %.632619621.us.2, 3
  %scevgep339 = getelementptr i8, ptr %scevgep928, i64 %236
  %scevgep340 = getelementptr i8, ptr %scevgep339, i64 -40
  %.720.us.2.2 = load double, ptr %scevgep340, align 8
  %.722.us.2.2 = fmul double %arg.h, %.720.us.2.2
  %.723.us.2.2 = fadd double %.691.us.2.2, %.722.us.2.2
  %sunkaddr1266 = mul i64 %.632619621.us.2, 8
  %sunkaddr1267 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1266
  %sunkaddr1268 = getelementptr i8, ptr %sunkaddr1267, i64 16
  store double %.723.us.2.2, ptr %sunkaddr1268, align 8
  %sunkaddr1269 = mul i64 %.632619621.us.2, 8
  %sunkaddr1270 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1269
  %sunkaddr1271 = getelementptr i8, ptr %sunkaddr1270, i64 24
  %.691.us.2.3 = load double, ptr %sunkaddr1271, align 8
  %237 = shl i64 %.632619621.us.2, 3
  %scevgep337 = getelementptr i8, ptr %scevgep928, i64 %237
  %scevgep338 = getelementptr i8, ptr %scevgep337, i64 -32
  %.720.us.2.3 = load double, ptr %scevgep338, align 8
  %.722.us.2.3 = fmul double %arg.h, %.720.us.2.3
  %.723.us.2.3 = fadd double %.691.us.2.3, %.722.us.2.3
  %sunkaddr1272 = mul i64 %.632619621.us.2, 8
  %sunkaddr1273 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1272
  %sunkaddr1274 = getelementptr i8, ptr %sunkaddr1273, i64 24
  store double %.723.us.2.3, ptr %sunkaddr1274, align 8
  %sunkaddr1275 = mul i64 %.632619621.us.2, 8
  %sunkaddr1276 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1275
  %sunkaddr1277 = getelementptr i8, ptr %sunkaddr1276, i64 32
  %.691.us.2.4 = load double, ptr %sunkaddr1277, align 8
  %238 = shl i64 %.632619621.us.2, 3
  %scevgep335 = getelementptr i8, ptr %scevgep928, i64 %238
  %scevgep336 = getelementptr i8, ptr %scevgep335, i64 -24
  %.720.us.2.4 = load double, ptr %scevgep336, align 8
  %.722.us.2.4 = fmul double %arg.h, %.720.us.2.4
  %.723.us.2.4 = fadd double %.691.us.2.4, %.722.us.2.4
  %sunkaddr1278 = mul i64 %.632619621.us.2, 8
  %sunkaddr1279 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1278
  %sunkaddr1280 = getelementptr i8, ptr %sunkaddr1279, i64 32
  store double %.723.us.2.4, ptr %sunkaddr1280, align 8
  %sunkaddr1281 = mul i64 %.632619621.us.2, 8
  %sunkaddr1282 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1281
  %sunkaddr1283 = getelementptr i8, ptr %sunkaddr1282, i64 40
  %.691.us.2.5 = load double, ptr %sunkaddr1283, align 8
  %239 = shl i64 %.632619621.us.2, 3
  %scevgep333 = getelementptr i8, ptr %scevgep928, i64 %239
  %scevgep334 = getelementptr i8, ptr %scevgep333, i64 -16
  %.720.us.2.5 = load double, ptr %scevgep334, align 8
  %.722.us.2.5 = fmul double %arg.h, %.720.us.2.5
  %.723.us.2.5 = fadd double %.691.us.2.5, %.722.us.2.5
  %sunkaddr1284 = mul i64 %.632619621.us.2, 8
  %sunkaddr1285 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1284
  %sunkaddr1286 = getelementptr i8, ptr %sunkaddr1285, i64 40
  store double %.723.us.2.5, ptr %sunkaddr1286, align 8
  %sunkaddr1287 = mul i64 %.632619621.us.2, 8
  %sunkaddr1288 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1287
  %sunkaddr1289 = getelementptr i8, ptr %sunkaddr1288, i64 48
  %.691.us.2.6 = load double, ptr %sunkaddr1289, align 8
  %240 = shl i64 %.632619621.us.2, 3
  %scevgep331 = getelementptr i8, ptr %scevgep928, i64 %240
  %scevgep332 = getelementptr i8, ptr %scevgep331, i64 -8
  %.720.us.2.6 = load double, ptr %scevgep332, align 8
  %.722.us.2.6 = fmul double %arg.h, %.720.us.2.6
  %.723.us.2.6 = fadd double %.691.us.2.6, %.722.us.2.6
  %sunkaddr1290 = mul i64 %.632619621.us.2, 8
  %sunkaddr1291 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1290
  %sunkaddr1292 = getelementptr i8, ptr %sunkaddr1291, i64 48
  store double %.723.us.2.6, ptr %sunkaddr1292, align 8
  %.639.us.2.7 = add nuw nsw i64 %.632619621.us.2, 8
  %sunkaddr1293 = mul i64 %.632619621.us.2, 8
  %sunkaddr1294 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1293
  %sunkaddr1295 = getelementptr i8, ptr %sunkaddr1294, i64 56
  %.691.us.2.7 = load double, ptr %sunkaddr1295, align 8
  %.720.us.2.7 = load double, ptr %scevgep940, align 8
  %.722.us.2.7 = fmul double %arg.h, %.720.us.2.7
  %.723.us.2.7 = fadd double %.691.us.2.7, %.722.us.2.7
  %sunkaddr1296 = mul i64 %.632619621.us.2, 8
  %sunkaddr1297 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1296
  %sunkaddr1298 = getelementptr i8, ptr %sunkaddr1297, i64 56
  store double %.723.us.2.7, ptr %sunkaddr1298, align 8
  %exitcond688.2.not.7 = icmp eq i64 %arg.y.2, %.639.us.2.7
  br i1 %exitcond688.2.not.7, label %B13409637.us.2, label %B13409633.us.2, !llvm.loop !49

B13409637.us.2:                                   ; preds = %B13409633.us.2, %B13409633.us.2.prol.loopexit, %vec.epilog.middle.block270, %middle.block254, %B13409637.endif.endif.us.1
  %.806.us.2.idx = mul i64 %arg.K.5.1, 24
  %.806.us.2 = getelementptr i8, ptr %arg.K.4, i64 %.806.us.2.idx
  %.834.fca.4.insert.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.268.fca.3.insert, ptr %.806.us.2, 4
  %.834.fca.5.0.insert.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.4.insert.us.2, i64 %arg.K.5.1, 5, 0
  %.834.fca.6.0.insert.us.2 = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.5.0.insert.us.2, i64 %arg.K.6.1, 6, 0
  %.885.us.2 = call double %arg.f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.543.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.270.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.834.fca.6.0.insert.us.2)
  %.10.i9 = fcmp olt double %.885.us.2, %.11.i8
  %.11.i10 = select i1 %.10.i9, double %.885.us.2, double %.11.i8
  br label %B13409639.endif

B13409633.us:                                     ; preds = %B13409633.us.preheader28, %B13409633.us
  %.632619621.us = phi i64 [ %.639.us.7, %B13409633.us ], [ %.632619621.us.unr, %B13409633.us.preheader28 ]
  %sunkaddr1299 = mul i64 %.632619621.us, 8
  %sunkaddr1300 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1299
  %.691.us = load double, ptr %sunkaddr1300, align 8
  %sunkaddr1301 = mul i64 %.632619621.us, 8
  %sunkaddr1302 = getelementptr i8, ptr %.172, i64 %sunkaddr1301
  %.720.us = load double, ptr %sunkaddr1302, align 8
  %.722.us = fmul double %.524.us.us, %.720.us
  %.723.us = fadd double %.691.us, %.722.us
  %sunkaddr1303 = mul i64 %.632619621.us, 8
  %sunkaddr1304 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1303
  store double %.723.us, ptr %sunkaddr1304, align 8
  %sunkaddr1305 = mul i64 %.632619621.us, 8
  %sunkaddr1306 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1305
  %sunkaddr1307 = getelementptr i8, ptr %sunkaddr1306, i64 8
  %.691.us.1510 = load double, ptr %sunkaddr1307, align 8
  %sunkaddr1308 = mul i64 %.632619621.us, 8
  %sunkaddr1309 = getelementptr i8, ptr %.172, i64 %sunkaddr1308
  %sunkaddr1310 = getelementptr i8, ptr %sunkaddr1309, i64 8
  %.720.us.1512 = load double, ptr %sunkaddr1310, align 8
  %.722.us.1513 = fmul double %.524.us.us, %.720.us.1512
  %.723.us.1514 = fadd double %.691.us.1510, %.722.us.1513
  %sunkaddr1311 = mul i64 %.632619621.us, 8
  %sunkaddr1312 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1311
  %sunkaddr1313 = getelementptr i8, ptr %sunkaddr1312, i64 8
  store double %.723.us.1514, ptr %sunkaddr1313, align 8
  %sunkaddr1314 = mul i64 %.632619621.us, 8
  %sunkaddr1315 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1314
  %sunkaddr1316 = getelementptr i8, ptr %sunkaddr1315, i64 16
  %.691.us.2520 = load double, ptr %sunkaddr1316, align 8
  %sunkaddr1317 = mul i64 %.632619621.us, 8
  %sunkaddr1318 = getelementptr i8, ptr %.172, i64 %sunkaddr1317
  %sunkaddr1319 = getelementptr i8, ptr %sunkaddr1318, i64 16
  %.720.us.2522 = load double, ptr %sunkaddr1319, align 8
  %.722.us.2523 = fmul double %.524.us.us, %.720.us.2522
  %.723.us.2524 = fadd double %.691.us.2520, %.722.us.2523
  %sunkaddr1320 = mul i64 %.632619621.us, 8
  %sunkaddr1321 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1320
  %sunkaddr1322 = getelementptr i8, ptr %sunkaddr1321, i64 16
  store double %.723.us.2524, ptr %sunkaddr1322, align 8
  %sunkaddr1323 = mul i64 %.632619621.us, 8
  %sunkaddr1324 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1323
  %sunkaddr1325 = getelementptr i8, ptr %sunkaddr1324, i64 24
  %.691.us.3 = load double, ptr %sunkaddr1325, align 8
  %sunkaddr1326 = mul i64 %.632619621.us, 8
  %sunkaddr1327 = getelementptr i8, ptr %.172, i64 %sunkaddr1326
  %sunkaddr1328 = getelementptr i8, ptr %sunkaddr1327, i64 24
  %.720.us.3 = load double, ptr %sunkaddr1328, align 8
  %.722.us.3 = fmul double %.524.us.us, %.720.us.3
  %.723.us.3 = fadd double %.691.us.3, %.722.us.3
  %sunkaddr1329 = mul i64 %.632619621.us, 8
  %sunkaddr1330 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1329
  %sunkaddr1331 = getelementptr i8, ptr %sunkaddr1330, i64 24
  store double %.723.us.3, ptr %sunkaddr1331, align 8
  %sunkaddr1332 = mul i64 %.632619621.us, 8
  %sunkaddr1333 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1332
  %sunkaddr1334 = getelementptr i8, ptr %sunkaddr1333, i64 32
  %.691.us.4 = load double, ptr %sunkaddr1334, align 8
  %sunkaddr1335 = mul i64 %.632619621.us, 8
  %sunkaddr1336 = getelementptr i8, ptr %.172, i64 %sunkaddr1335
  %sunkaddr1337 = getelementptr i8, ptr %sunkaddr1336, i64 32
  %.720.us.4 = load double, ptr %sunkaddr1337, align 8
  %.722.us.4 = fmul double %.524.us.us, %.720.us.4
  %.723.us.4 = fadd double %.691.us.4, %.722.us.4
  %sunkaddr1338 = mul i64 %.632619621.us, 8
  %sunkaddr1339 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1338
  %sunkaddr1340 = getelementptr i8, ptr %sunkaddr1339, i64 32
  store double %.723.us.4, ptr %sunkaddr1340, align 8
  %sunkaddr1341 = mul i64 %.632619621.us, 8
  %sunkaddr1342 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1341
  %sunkaddr1343 = getelementptr i8, ptr %sunkaddr1342, i64 40
  %.691.us.5 = load double, ptr %sunkaddr1343, align 8
  %sunkaddr1344 = mul i64 %.632619621.us, 8
  %sunkaddr1345 = getelementptr i8, ptr %.172, i64 %sunkaddr1344
  %sunkaddr1346 = getelementptr i8, ptr %sunkaddr1345, i64 40
  %.720.us.5 = load double, ptr %sunkaddr1346, align 8
  %.722.us.5 = fmul double %.524.us.us, %.720.us.5
  %.723.us.5 = fadd double %.691.us.5, %.722.us.5
  %sunkaddr1347 = mul i64 %.632619621.us, 8
  %sunkaddr1348 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1347
  %sunkaddr1349 = getelementptr i8, ptr %sunkaddr1348, i64 40
  store double %.723.us.5, ptr %sunkaddr1349, align 8
  %sunkaddr1350 = mul i64 %.632619621.us, 8
  %sunkaddr1351 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1350
  %sunkaddr1352 = getelementptr i8, ptr %sunkaddr1351, i64 48
  %.691.us.6 = load double, ptr %sunkaddr1352, align 8
  %sunkaddr1353 = mul i64 %.632619621.us, 8
  %sunkaddr1354 = getelementptr i8, ptr %.172, i64 %sunkaddr1353
  %sunkaddr1355 = getelementptr i8, ptr %sunkaddr1354, i64 48
  %.720.us.6 = load double, ptr %sunkaddr1355, align 8
  %.722.us.6 = fmul double %.524.us.us, %.720.us.6
  %.723.us.6 = fadd double %.691.us.6, %.722.us.6
  %sunkaddr1356 = mul i64 %.632619621.us, 8
  %sunkaddr1357 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1356
  %sunkaddr1358 = getelementptr i8, ptr %sunkaddr1357, i64 48
  store double %.723.us.6, ptr %sunkaddr1358, align 8
  %.639.us.7 = add nuw nsw i64 %.632619621.us, 8
  %sunkaddr1359 = mul i64 %.632619621.us, 8
  %sunkaddr1360 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1359
  %sunkaddr1361 = getelementptr i8, ptr %sunkaddr1360, i64 56
  %.691.us.7 = load double, ptr %sunkaddr1361, align 8
  %sunkaddr1362 = mul i64 %.632619621.us, 8
  %sunkaddr1363 = getelementptr i8, ptr %.172, i64 %sunkaddr1362
  %sunkaddr1364 = getelementptr i8, ptr %sunkaddr1363, i64 56
  %.720.us.7 = load double, ptr %sunkaddr1364, align 8
  %.722.us.7 = fmul double %.524.us.us, %.720.us.7
  %.723.us.7 = fadd double %.691.us.7, %.722.us.7
  %sunkaddr1365 = mul i64 %.632619621.us, 8
  %sunkaddr1366 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1365
  %sunkaddr1367 = getelementptr i8, ptr %sunkaddr1366, i64 56
  store double %.723.us.7, ptr %sunkaddr1367, align 8
  %exitcond688.not.7 = icmp eq i64 %arg.y.2, %.639.us.7
  br i1 %exitcond688.not.7, label %B13409637.endif.endif.us, label %B13409633.us, !llvm.loop !50

B13409637.if.if.if:                               ; preds = %B13409637.us.us.2, %B13409637.us.us.1, %B13409637.us.us
  store ptr @.const.picklebuf.772380b16aa618530594268027b0fd5294b03a2b, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B13409637.else.if.if:                             ; preds = %B13409637.2, %B13409637.1, %B13409637
  %.899.lcssa = phi i32 [ %.899, %B13409637 ], [ %.899.1, %B13409637.1 ], [ %.899.2, %B13409637.2 ]
  %.907 = icmp sgt i32 %.899.lcssa, 0
  %.900 = load ptr, ptr %excinfo.3, align 8
  %.908 = select i1 %.907, ptr %.900, ptr undef
  store ptr %.908, ptr %excinfo, align 8
  br label %common.ret

B13409637.endif.endif:                            ; preds = %B13409637, %B13409637
  %241 = icmp slt i64 %arg.y.2, 1
  %.909 = load double, ptr %.889, align 8
  %.10.i11 = fcmp olt double %.909, %.278.0
  %.11.i12 = select i1 %.10.i11, double %.909, double %.278.0
  br i1 %241, label %B13409637.1, label %iter.check51

iter.check51:                                     ; preds = %B13409637.endif.endif
  %242 = getelementptr double, ptr %.172, i64 %arg.y.2
  %min.iters.check49 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check49, label %B13409633.1.preheader, label %vector.memcheck43

vector.memcheck43:                                ; preds = %iter.check51
  %243 = ptrtoint ptr %.172 to i64
  %244 = ptrtoint ptr %arg.ytmp.4 to i64
  %245 = ptrtoint ptr %arg.y.4 to i64
  %246 = sub i64 %244, %245
  %diff.check46 = icmp ult i64 %246, 256
  %247 = shl i64 %arg.y.2, 3
  %248 = add i64 %247, %243
  %249 = sub i64 %244, %248
  %diff.check47 = icmp ult i64 %249, 256
  %conflict.rdx48 = or i1 %diff.check46, %diff.check47
  br i1 %conflict.rdx48, label %B13409633.1.preheader, label %vector.main.loop.iter.check53

vector.main.loop.iter.check53:                    ; preds = %vector.memcheck43
  %const750 = bitcast i64 9223372036854775776 to i64
  %min.iters.check52 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check52, label %vec.epilog.ph76, label %vector.ph54

vector.ph54:                                      ; preds = %vector.main.loop.iter.check53
  %n.vec56 = and i64 %arg.y.2, %const750
  %broadcast.splatinsert57 = insertelement <8 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat58 = shufflevector <8 x double> %broadcast.splatinsert57, <8 x double> poison, <8 x i32> zeroinitializer
  %250 = getelementptr i8, ptr %.172, i64 %247
  %scevgep1296 = getelementptr i8, ptr %250, i64 192
  br label %vector.body59

vector.body59:                                    ; preds = %vector.body59, %vector.ph54
  %index60 = phi i64 [ 0, %vector.ph54 ], [ %index.next69, %vector.body59 ]
  %sunkaddr1368 = mul i64 %index60, 8
  %sunkaddr1369 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1368
  %wide.load61 = load <8 x double>, ptr %sunkaddr1369, align 8
  %sunkaddr1370 = mul i64 %index60, 8
  %sunkaddr1371 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1370
  %sunkaddr1372 = getelementptr i8, ptr %sunkaddr1371, i64 64
  %wide.load62 = load <8 x double>, ptr %sunkaddr1372, align 8
  %sunkaddr1373 = mul i64 %index60, 8
  %sunkaddr1374 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1373
  %sunkaddr1375 = getelementptr i8, ptr %sunkaddr1374, i64 128
  %wide.load63 = load <8 x double>, ptr %sunkaddr1375, align 8
  %sunkaddr1376 = mul i64 %index60, 8
  %sunkaddr1377 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1376
  %sunkaddr1378 = getelementptr i8, ptr %sunkaddr1377, i64 192
  %wide.load64 = load <8 x double>, ptr %sunkaddr1378, align 8
  %251 = shl i64 %index60, 3
  %scevgep656 = getelementptr i8, ptr %scevgep1296, i64 %251
  %scevgep659 = getelementptr i8, ptr %scevgep656, i64 -192
  %scevgep658 = getelementptr i8, ptr %scevgep656, i64 -128
  %scevgep657 = getelementptr i8, ptr %scevgep656, i64 -64
  %wide.load65 = load <8 x double>, ptr %scevgep659, align 8
  %wide.load66 = load <8 x double>, ptr %scevgep658, align 8
  %wide.load67 = load <8 x double>, ptr %scevgep657, align 8
  %wide.load68 = load <8 x double>, ptr %scevgep656, align 8
  %252 = fmul <8 x double> %broadcast.splat58, %wide.load65
  %253 = fmul <8 x double> %broadcast.splat58, %wide.load66
  %254 = fmul <8 x double> %broadcast.splat58, %wide.load67
  %255 = fmul <8 x double> %broadcast.splat58, %wide.load68
  %256 = fadd <8 x double> %wide.load61, %252
  %257 = fadd <8 x double> %wide.load62, %253
  %258 = fadd <8 x double> %wide.load63, %254
  %259 = fadd <8 x double> %wide.load64, %255
  %sunkaddr1379 = mul i64 %index60, 8
  %sunkaddr1380 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1379
  store <8 x double> %256, ptr %sunkaddr1380, align 8
  %sunkaddr1381 = mul i64 %index60, 8
  %sunkaddr1382 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1381
  %sunkaddr1383 = getelementptr i8, ptr %sunkaddr1382, i64 64
  store <8 x double> %257, ptr %sunkaddr1383, align 8
  %sunkaddr1384 = mul i64 %index60, 8
  %sunkaddr1385 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1384
  %sunkaddr1386 = getelementptr i8, ptr %sunkaddr1385, i64 128
  store <8 x double> %258, ptr %sunkaddr1386, align 8
  %sunkaddr1387 = mul i64 %index60, 8
  %sunkaddr1388 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1387
  %sunkaddr1389 = getelementptr i8, ptr %sunkaddr1388, i64 192
  store <8 x double> %259, ptr %sunkaddr1389, align 8
  %index.next69 = add nuw nsw i64 %index60, 32
  %260 = icmp eq i64 %n.vec56, %index.next69
  br i1 %260, label %middle.block70, label %vector.body59, !llvm.loop !51

middle.block70:                                   ; preds = %vector.body59
  %cmp.n71 = icmp eq i64 %arg.y.2, %n.vec56
  br i1 %cmp.n71, label %B13409637.1, label %vec.epilog.iter.check74

vec.epilog.iter.check74:                          ; preds = %middle.block70
  %261 = and i64 %arg.y.2, 28
  %min.epilog.iters.check75 = icmp eq i64 %261, 0
  br i1 %min.epilog.iters.check75, label %B13409633.1.preheader, label %vec.epilog.ph76, !prof !9

vec.epilog.ph76:                                  ; preds = %vec.epilog.iter.check74, %vector.main.loop.iter.check53
  %vec.epilog.resume.val72 = phi i64 [ %n.vec56, %vec.epilog.iter.check74 ], [ 0, %vector.main.loop.iter.check53 ]
  %const_mat751 = add i64 %const750, 28
  %n.vec78 = and i64 %arg.y.2, %const_mat751
  %broadcast.splatinsert79 = insertelement <4 x double> poison, double %.524.us.us, i64 0
  %broadcast.splat80 = shufflevector <4 x double> %broadcast.splatinsert79, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body81

vec.epilog.vector.body81:                         ; preds = %vec.epilog.vector.body81, %vec.epilog.ph76
  %index82 = phi i64 [ %vec.epilog.resume.val72, %vec.epilog.ph76 ], [ %index.next85, %vec.epilog.vector.body81 ]
  %262 = shl i64 %index82, 3
  %scevgep1287 = getelementptr i8, ptr %arg.y.4, i64 %262
  %wide.load83 = load <4 x double>, ptr %scevgep1287, align 8
  %scevgep1286 = getelementptr i8, ptr %242, i64 %262
  %wide.load84 = load <4 x double>, ptr %scevgep1286, align 8
  %263 = fmul <4 x double> %broadcast.splat80, %wide.load84
  %264 = fadd <4 x double> %wide.load83, %263
  %265 = shl i64 %index82, 3
  %scevgep647 = getelementptr i8, ptr %arg.ytmp.4, i64 %265
  store <4 x double> %264, ptr %scevgep647, align 8
  %index.next85 = add nuw i64 %index82, 4
  %266 = icmp eq i64 %n.vec78, %index.next85
  br i1 %266, label %vec.epilog.middle.block86, label %vec.epilog.vector.body81, !llvm.loop !52

vec.epilog.middle.block86:                        ; preds = %vec.epilog.vector.body81
  %cmp.n87 = icmp eq i64 %arg.y.2, %n.vec78
  br i1 %cmp.n87, label %B13409637.1, label %B13409633.1.preheader

B13409633.1.preheader:                            ; preds = %vec.epilog.middle.block86, %vec.epilog.iter.check74, %vector.memcheck43, %iter.check51
  %.632619621.1.ph = phi i64 [ 0, %iter.check51 ], [ 0, %vector.memcheck43 ], [ %n.vec56, %vec.epilog.iter.check74 ], [ %n.vec78, %vec.epilog.middle.block86 ]
  %267 = sub nsw i64 %arg.y.2, %.632619621.1.ph
  %xtraiter498 = and i64 %267, 7
  %lcmp.mod499.not = icmp eq i64 %xtraiter498, 0
  br i1 %lcmp.mod499.not, label %B13409633.1.prol.loopexit, label %B13409633.1.prol.preheader

B13409633.1.prol.preheader:                       ; preds = %B13409633.1.preheader
  br label %B13409633.1.prol

B13409633.1.prol:                                 ; preds = %B13409633.1.prol.preheader, %B13409633.1.prol
  %lsr.iv1283 = phi i64 [ %lsr.iv.next1284, %B13409633.1.prol ], [ %xtraiter498, %B13409633.1.prol.preheader ]
  %.632619621.1.prol = phi i64 [ %.639.1.prol, %B13409633.1.prol ], [ %.632619621.1.ph, %B13409633.1.prol.preheader ]
  %.639.1.prol = add nuw i64 %.632619621.1.prol, 1
  %268 = shl i64 %.632619621.1.prol, 3
  %scevgep1282 = getelementptr i8, ptr %arg.y.4, i64 %268
  %.691.1.prol = load double, ptr %scevgep1282, align 8
  %scevgep1281 = getelementptr i8, ptr %242, i64 %268
  %.720.1.prol = load double, ptr %scevgep1281, align 8
  %.722.1.prol = fmul double %.524.us.us, %.720.1.prol
  %.723.1.prol = fadd double %.691.1.prol, %.722.1.prol
  %269 = shl i64 %.632619621.1.prol, 3
  %scevgep646 = getelementptr i8, ptr %arg.ytmp.4, i64 %269
  store double %.723.1.prol, ptr %scevgep646, align 8
  %lsr.iv.next1284 = add nsw i64 %lsr.iv1283, -1
  %prol.iter500.cmp.not = icmp eq i64 %lsr.iv.next1284, 0
  br i1 %prol.iter500.cmp.not, label %B13409633.1.prol.loopexit, label %B13409633.1.prol, !llvm.loop !53

B13409633.1.prol.loopexit:                        ; preds = %B13409633.1.prol, %B13409633.1.preheader
  %.632619621.1.unr = phi i64 [ %.632619621.1.ph, %B13409633.1.preheader ], [ %.639.1.prol, %B13409633.1.prol ]
  %270 = sub nsw i64 %.632619621.1.ph, %arg.y.2
  %271 = icmp ugt i64 %270, -8
  br i1 %271, label %B13409637.1, label %B13409633.1.preheader573

B13409633.1.preheader573:                         ; preds = %B13409633.1.prol.loopexit
  %272 = shl i64 %arg.y.2, 3
  %273 = getelementptr i8, ptr %.172, i64 %272
  %scevgep1248 = getelementptr i8, ptr %273, i64 56
  br label %B13409633.1

B13409633.1:                                      ; preds = %B13409633.1, %B13409633.1.preheader573
  %.632619621.1 = phi i64 [ %.639.1.7, %B13409633.1 ], [ %.632619621.1.unr, %B13409633.1.preheader573 ]
  %sunkaddr2010 = shl i64 %.632619621.1, 3
  %sunkaddr1390 = mul i64 %.632619621.1, 8
  %sunkaddr1391 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1390
  %.691.1 = load double, ptr %sunkaddr1391, align 8
  %scevgep1260 = getelementptr i8, ptr %scevgep1248, i64 %sunkaddr2010
  %scevgep1261 = getelementptr i8, ptr %scevgep1260, i64 -56
  %.720.1 = load double, ptr %scevgep1261, align 8
  %.722.1 = fmul double %.524.us.us, %.720.1
  %.723.1 = fadd double %.691.1, %.722.1
  %sunkaddr1392 = mul i64 %.632619621.1, 8
  %sunkaddr1393 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1392
  store double %.723.1, ptr %sunkaddr1393, align 8
  %sunkaddr1394 = mul i64 %.632619621.1, 8
  %sunkaddr1395 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1394
  %sunkaddr1396 = getelementptr i8, ptr %sunkaddr1395, i64 8
  %.691.1.1 = load double, ptr %sunkaddr1396, align 8
  %274 = shl i64 %.632619621.1, 3
  %scevgep617 = getelementptr i8, ptr %scevgep1248, i64 %274
  %scevgep620 = getelementptr i8, ptr %scevgep617, i64 -48
  %.720.1.1 = load double, ptr %scevgep620, align 8
  %.722.1.1 = fmul double %.524.us.us, %.720.1.1
  %.723.1.1 = fadd double %.691.1.1, %.722.1.1
  %sunkaddr1397 = mul i64 %.632619621.1, 8
  %sunkaddr1398 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1397
  %sunkaddr1399 = getelementptr i8, ptr %sunkaddr1398, i64 8
  store double %.723.1.1, ptr %sunkaddr1399, align 8
  %sunkaddr1400 = mul i64 %.632619621.1, 8
  %sunkaddr1401 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1400
  %sunkaddr1402 = getelementptr i8, ptr %sunkaddr1401, i64 16
  %.691.1.2 = load double, ptr %sunkaddr1402, align 8
  %275 = shl i64 %.632619621.1, 3
  %scevgep615 = getelementptr i8, ptr %scevgep1248, i64 %275
  %scevgep616 = getelementptr i8, ptr %scevgep615, i64 -40
  %.720.1.2 = load double, ptr %scevgep616, align 8
  %.722.1.2 = fmul double %.524.us.us, %.720.1.2
  %.723.1.2 = fadd double %.691.1.2, %.722.1.2
  %sunkaddr1403 = mul i64 %.632619621.1, 8
  %sunkaddr1404 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1403
  %sunkaddr1405 = getelementptr i8, ptr %sunkaddr1404, i64 16
  store double %.723.1.2, ptr %sunkaddr1405, align 8
  %sunkaddr1406 = mul i64 %.632619621.1, 8
  %sunkaddr1407 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1406
  %sunkaddr1408 = getelementptr i8, ptr %sunkaddr1407, i64 24
  %.691.1.3 = load double, ptr %sunkaddr1408, align 8
  %276 = shl i64 %.632619621.1, 3
  %scevgep612 = getelementptr i8, ptr %scevgep1248, i64 %276
  %scevgep613 = getelementptr i8, ptr %scevgep612, i64 -32
  %.720.1.3 = load double, ptr %scevgep613, align 8
  %.722.1.3 = fmul double %.524.us.us, %.720.1.3
  %.723.1.3 = fadd double %.691.1.3, %.722.1.3
  %sunkaddr1409 = mul i64 %.632619621.1, 8
  %sunkaddr1410 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1409
  %sunkaddr1411 = getelementptr i8, ptr %sunkaddr1410, i64 24
  store double %.723.1.3, ptr %sunkaddr1411, align 8
  %sunkaddr1412 = mul i64 %.632619621.1, 8
  %sunkaddr1413 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1412
  %sunkaddr1414 = getelementptr i8, ptr %sunkaddr1413, i64 32
  %.691.1.4 = load double, ptr %sunkaddr1414, align 8
  %277 = shl i64 %.632619621.1, 3
  %scevgep610 = getelementptr i8, ptr %scevgep1248, i64 %277
  %scevgep611 = getelementptr i8, ptr %scevgep610, i64 -24
  %.720.1.4 = load double, ptr %scevgep611, align 8
  %.722.1.4 = fmul double %.524.us.us, %.720.1.4
  %.723.1.4 = fadd double %.691.1.4, %.722.1.4
  %sunkaddr1415 = mul i64 %.632619621.1, 8
  %sunkaddr1416 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1415
  %sunkaddr1417 = getelementptr i8, ptr %sunkaddr1416, i64 32
  store double %.723.1.4, ptr %sunkaddr1417, align 8
  %sunkaddr1418 = mul i64 %.632619621.1, 8
  %sunkaddr1419 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1418
  %sunkaddr1420 = getelementptr i8, ptr %sunkaddr1419, i64 40
  %.691.1.5 = load double, ptr %sunkaddr1420, align 8
  %278 = shl i64 %.632619621.1, 3
  %scevgep608 = getelementptr i8, ptr %scevgep1248, i64 %278
  %scevgep609 = getelementptr i8, ptr %scevgep608, i64 -16
  %.720.1.5 = load double, ptr %scevgep609, align 8
  %.722.1.5 = fmul double %.524.us.us, %.720.1.5
  %.723.1.5 = fadd double %.691.1.5, %.722.1.5
  %sunkaddr1421 = mul i64 %.632619621.1, 8
  %sunkaddr1422 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1421
  %sunkaddr1423 = getelementptr i8, ptr %sunkaddr1422, i64 40
  store double %.723.1.5, ptr %sunkaddr1423, align 8
  %sunkaddr1424 = mul i64 %.632619621.1, 8
  %sunkaddr1425 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1424
  %sunkaddr1426 = getelementptr i8, ptr %sunkaddr1425, i64 48
  %.691.1.6 = load double, ptr %sunkaddr1426, align 8
  %279 = shl i64 %.632619621.1, 3
  %scevgep606 = getelementptr i8, ptr %scevgep1248, i64 %279
  %scevgep607 = getelementptr i8, ptr %scevgep606, i64 -8
  %.720.1.6 = load double, ptr %scevgep607, align 8
  %.722.1.6 = fmul double %.524.us.us, %.720.1.6
  %.723.1.6 = fadd double %.691.1.6, %.722.1.6
  %sunkaddr1427 = mul i64 %.632619621.1, 8
  %sunkaddr1428 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1427
  %sunkaddr1429 = getelementptr i8, ptr %sunkaddr1428, i64 48
  store double %.723.1.6, ptr %sunkaddr1429, align 8
  %.639.1.7 = add nuw nsw i64 %.632619621.1, 8
  %sunkaddr1430 = mul i64 %.632619621.1, 8
  %sunkaddr1431 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1430
  %sunkaddr1432 = getelementptr i8, ptr %sunkaddr1431, i64 56
  %.691.1.7 = load double, ptr %sunkaddr1432, align 8
  %.720.1.7 = load double, ptr %scevgep1260, align 8
  %.722.1.7 = fmul double %.524.us.us, %.720.1.7
  %.723.1.7 = fadd double %.691.1.7, %.722.1.7
  %sunkaddr1433 = mul i64 %.632619621.1, 8
  %sunkaddr1434 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1433
  %sunkaddr1435 = getelementptr i8, ptr %sunkaddr1434, i64 56
  store double %.723.1.7, ptr %sunkaddr1435, align 8
  %exitcond.1.not.7 = icmp eq i64 %arg.y.2, %.639.1.7
  br i1 %exitcond.1.not.7, label %B13409637.1, label %B13409633.1, !llvm.loop !54

B13409637.1:                                      ; preds = %B13409633.1, %B13409633.1.prol.loopexit, %vec.epilog.middle.block86, %middle.block70, %B13409637.endif.endif
  %.806.1.idx = shl i64 %arg.K.5.1, 4
  %.806.1 = getelementptr i8, ptr %arg.K.4, i64 %.806.1.idx
  store double 0.000000e+00, ptr %.889, align 8
  %.899.1 = call i32 %arg.f.2(ptr nonnull %.889, ptr nonnull %excinfo.3, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.806.1, i64 %arg.K.5.1, i64 %arg.K.6.1)
  switch i32 %.899.1, label %B13409637.else.if.if [
    i32 -2, label %B13409637.endif.endif.1
    i32 0, label %B13409637.endif.endif.1
  ], !prof !4

B13409637.endif.endif.1:                          ; preds = %B13409637.1, %B13409637.1
  %280 = icmp slt i64 %arg.y.2, 1
  %.909.1 = load double, ptr %.889, align 8
  %.10.i13 = fcmp olt double %.909.1, %.11.i12
  %.11.i14 = select i1 %.10.i13, double %.909.1, double %.11.i12
  br i1 %280, label %B13409637.2, label %iter.check97

iter.check97:                                     ; preds = %B13409637.endif.endif.1
  %.idx691 = shl i64 %arg.y.2, 4
  %281 = getelementptr i8, ptr %.172, i64 %.idx691
  %min.iters.check95 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check95, label %B13409633.2.preheader, label %vector.memcheck89

vector.memcheck89:                                ; preds = %iter.check97
  %282 = ptrtoint ptr %.172 to i64
  %283 = ptrtoint ptr %arg.ytmp.4 to i64
  %284 = ptrtoint ptr %arg.y.4 to i64
  %285 = sub i64 %283, %284
  %diff.check92 = icmp ult i64 %285, 256
  %286 = add i64 %.idx691, %282
  %287 = sub i64 %283, %286
  %diff.check93 = icmp ult i64 %287, 256
  %conflict.rdx94 = or i1 %diff.check92, %diff.check93
  br i1 %conflict.rdx94, label %B13409633.2.preheader, label %vector.main.loop.iter.check99

vector.main.loop.iter.check99:                    ; preds = %vector.memcheck89
  %const752 = bitcast i64 9223372036854775776 to i64
  %min.iters.check98 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check98, label %vec.epilog.ph122, label %vector.ph100

vector.ph100:                                     ; preds = %vector.main.loop.iter.check99
  %n.vec102 = and i64 %arg.y.2, %const752
  %broadcast.splatinsert103 = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat104 = shufflevector <8 x double> %broadcast.splatinsert103, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body105

vector.body105:                                   ; preds = %vector.body105, %vector.ph100
  %index106 = phi i64 [ 0, %vector.ph100 ], [ %index.next115, %vector.body105 ]
  %sunkaddr1436 = mul i64 %index106, 8
  %sunkaddr1437 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1436
  %wide.load107 = load <8 x double>, ptr %sunkaddr1437, align 8
  %sunkaddr1438 = mul i64 %index106, 8
  %sunkaddr1439 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1438
  %sunkaddr1440 = getelementptr i8, ptr %sunkaddr1439, i64 64
  %wide.load108 = load <8 x double>, ptr %sunkaddr1440, align 8
  %sunkaddr1441 = mul i64 %index106, 8
  %sunkaddr1442 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1441
  %sunkaddr1443 = getelementptr i8, ptr %sunkaddr1442, i64 128
  %wide.load109 = load <8 x double>, ptr %sunkaddr1443, align 8
  %sunkaddr1444 = mul i64 %index106, 8
  %sunkaddr1445 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1444
  %sunkaddr1446 = getelementptr i8, ptr %sunkaddr1445, i64 192
  %wide.load110 = load <8 x double>, ptr %sunkaddr1446, align 8
  %sunkaddr1447 = mul i64 %index106, 8
  %sunkaddr1448 = getelementptr i8, ptr %281, i64 %sunkaddr1447
  %wide.load111 = load <8 x double>, ptr %sunkaddr1448, align 8
  %sunkaddr1449 = mul i64 %index106, 8
  %sunkaddr1450 = getelementptr i8, ptr %281, i64 %sunkaddr1449
  %sunkaddr1451 = getelementptr i8, ptr %sunkaddr1450, i64 64
  %wide.load112 = load <8 x double>, ptr %sunkaddr1451, align 8
  %sunkaddr1452 = mul i64 %index106, 8
  %sunkaddr1453 = getelementptr i8, ptr %281, i64 %sunkaddr1452
  %sunkaddr1454 = getelementptr i8, ptr %sunkaddr1453, i64 128
  %wide.load113 = load <8 x double>, ptr %sunkaddr1454, align 8
  %sunkaddr1455 = mul i64 %index106, 8
  %sunkaddr1456 = getelementptr i8, ptr %281, i64 %sunkaddr1455
  %sunkaddr1457 = getelementptr i8, ptr %sunkaddr1456, i64 192
  %wide.load114 = load <8 x double>, ptr %sunkaddr1457, align 8
  %288 = fmul <8 x double> %broadcast.splat104, %wide.load111
  %289 = fmul <8 x double> %broadcast.splat104, %wide.load112
  %290 = fmul <8 x double> %broadcast.splat104, %wide.load113
  %291 = fmul <8 x double> %broadcast.splat104, %wide.load114
  %292 = fadd <8 x double> %wide.load107, %288
  %293 = fadd <8 x double> %wide.load108, %289
  %294 = fadd <8 x double> %wide.load109, %290
  %295 = fadd <8 x double> %wide.load110, %291
  %sunkaddr1458 = mul i64 %index106, 8
  %sunkaddr1459 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1458
  store <8 x double> %292, ptr %sunkaddr1459, align 8
  %sunkaddr1460 = mul i64 %index106, 8
  %sunkaddr1461 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1460
  %sunkaddr1462 = getelementptr i8, ptr %sunkaddr1461, i64 64
  store <8 x double> %293, ptr %sunkaddr1462, align 8
  %sunkaddr1463 = mul i64 %index106, 8
  %sunkaddr1464 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1463
  %sunkaddr1465 = getelementptr i8, ptr %sunkaddr1464, i64 128
  store <8 x double> %294, ptr %sunkaddr1465, align 8
  %sunkaddr1466 = mul i64 %index106, 8
  %sunkaddr1467 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1466
  %sunkaddr1468 = getelementptr i8, ptr %sunkaddr1467, i64 192
  store <8 x double> %295, ptr %sunkaddr1468, align 8
  %index.next115 = add nuw nsw i64 %index106, 32
  %296 = icmp eq i64 %n.vec102, %index.next115
  br i1 %296, label %middle.block116, label %vector.body105, !llvm.loop !55

middle.block116:                                  ; preds = %vector.body105
  %cmp.n117 = icmp eq i64 %arg.y.2, %n.vec102
  br i1 %cmp.n117, label %B13409637.2, label %vec.epilog.iter.check120

vec.epilog.iter.check120:                         ; preds = %middle.block116
  %297 = and i64 %arg.y.2, 28
  %min.epilog.iters.check121 = icmp eq i64 %297, 0
  br i1 %min.epilog.iters.check121, label %B13409633.2.preheader, label %vec.epilog.ph122, !prof !9

vec.epilog.ph122:                                 ; preds = %vec.epilog.iter.check120, %vector.main.loop.iter.check99
  %vec.epilog.resume.val118 = phi i64 [ %n.vec102, %vec.epilog.iter.check120 ], [ 0, %vector.main.loop.iter.check99 ]
  %const_mat753 = add i64 %const752, 28
  %n.vec124 = and i64 %arg.y.2, %const_mat753
  %broadcast.splatinsert125 = insertelement <4 x double> poison, double %arg.h, i64 0
  %broadcast.splat126 = shufflevector <4 x double> %broadcast.splatinsert125, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body127

vec.epilog.vector.body127:                        ; preds = %vec.epilog.vector.body127, %vec.epilog.ph122
  %index128 = phi i64 [ %vec.epilog.resume.val118, %vec.epilog.ph122 ], [ %index.next131, %vec.epilog.vector.body127 ]
  %298 = shl i64 %index128, 3
  %scevgep1207 = getelementptr i8, ptr %arg.y.4, i64 %298
  %wide.load129 = load <4 x double>, ptr %scevgep1207, align 8
  %scevgep1206 = getelementptr i8, ptr %281, i64 %298
  %wide.load130 = load <4 x double>, ptr %scevgep1206, align 8
  %299 = fmul <4 x double> %broadcast.splat126, %wide.load130
  %300 = fadd <4 x double> %wide.load129, %299
  %301 = shl i64 %index128, 3
  %scevgep566 = getelementptr i8, ptr %arg.ytmp.4, i64 %301
  store <4 x double> %300, ptr %scevgep566, align 8
  %index.next131 = add nuw i64 %index128, 4
  %302 = icmp eq i64 %n.vec124, %index.next131
  br i1 %302, label %vec.epilog.middle.block132, label %vec.epilog.vector.body127, !llvm.loop !56

vec.epilog.middle.block132:                       ; preds = %vec.epilog.vector.body127
  %cmp.n133 = icmp eq i64 %arg.y.2, %n.vec124
  br i1 %cmp.n133, label %B13409637.2, label %B13409633.2.preheader

B13409633.2.preheader:                            ; preds = %vec.epilog.middle.block132, %vec.epilog.iter.check120, %vector.memcheck89, %iter.check97
  %.632619621.2.ph = phi i64 [ 0, %iter.check97 ], [ 0, %vector.memcheck89 ], [ %n.vec102, %vec.epilog.iter.check120 ], [ %n.vec124, %vec.epilog.middle.block132 ]
  %303 = sub nsw i64 %arg.y.2, %.632619621.2.ph
  %xtraiter501 = and i64 %303, 7
  %lcmp.mod502.not = icmp eq i64 %xtraiter501, 0
  br i1 %lcmp.mod502.not, label %B13409633.2.prol.loopexit, label %B13409633.2.prol.preheader

B13409633.2.prol.preheader:                       ; preds = %B13409633.2.preheader
  br label %B13409633.2.prol

B13409633.2.prol:                                 ; preds = %B13409633.2.prol.preheader, %B13409633.2.prol
  %lsr.iv1203 = phi i64 [ %lsr.iv.next1204, %B13409633.2.prol ], [ %xtraiter501, %B13409633.2.prol.preheader ]
  %.632619621.2.prol = phi i64 [ %.639.2.prol, %B13409633.2.prol ], [ %.632619621.2.ph, %B13409633.2.prol.preheader ]
  %.639.2.prol = add nuw i64 %.632619621.2.prol, 1
  %304 = shl i64 %.632619621.2.prol, 3
  %scevgep1202 = getelementptr i8, ptr %arg.y.4, i64 %304
  %.691.2.prol = load double, ptr %scevgep1202, align 8
  %scevgep1201 = getelementptr i8, ptr %281, i64 %304
  %.720.2.prol = load double, ptr %scevgep1201, align 8
  %.722.2.prol = fmul double %arg.h, %.720.2.prol
  %.723.2.prol = fadd double %.691.2.prol, %.722.2.prol
  %305 = shl i64 %.632619621.2.prol, 3
  %scevgep565 = getelementptr i8, ptr %arg.ytmp.4, i64 %305
  store double %.723.2.prol, ptr %scevgep565, align 8
  %lsr.iv.next1204 = add nsw i64 %lsr.iv1203, -1
  %prol.iter503.cmp.not = icmp eq i64 %lsr.iv.next1204, 0
  br i1 %prol.iter503.cmp.not, label %B13409633.2.prol.loopexit, label %B13409633.2.prol, !llvm.loop !57

B13409633.2.prol.loopexit:                        ; preds = %B13409633.2.prol, %B13409633.2.preheader
  %.632619621.2.unr = phi i64 [ %.632619621.2.ph, %B13409633.2.preheader ], [ %.639.2.prol, %B13409633.2.prol ]
  %306 = sub nsw i64 %.632619621.2.ph, %arg.y.2
  %307 = icmp ugt i64 %306, -8
  br i1 %307, label %B13409637.2, label %B13409633.2.preheader572

B13409633.2.preheader572:                         ; preds = %B13409633.2.prol.loopexit
  %scevgep1168 = getelementptr i8, ptr %281, i64 56
  br label %B13409633.2

B13409633.2:                                      ; preds = %B13409633.2, %B13409633.2.preheader572
  %.632619621.2 = phi i64 [ %.639.2.7, %B13409633.2 ], [ %.632619621.2.unr, %B13409633.2.preheader572 ]
  %sunkaddr2078 = shl i64 %.632619621.2, 3
  %sunkaddr1469 = mul i64 %.632619621.2, 8
  %sunkaddr1470 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1469
  %.691.2 = load double, ptr %sunkaddr1470, align 8
  %scevgep1180 = getelementptr i8, ptr %scevgep1168, i64 %sunkaddr2078
  %scevgep1181 = getelementptr i8, ptr %scevgep1180, i64 -56
  %.720.2 = load double, ptr %scevgep1181, align 8
  %.722.2 = fmul double %arg.h, %.720.2
  %.723.2 = fadd double %.691.2, %.722.2
  %sunkaddr1471 = mul i64 %.632619621.2, 8
  %sunkaddr1472 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1471
  store double %.723.2, ptr %sunkaddr1472, align 8
  %sunkaddr1473 = mul i64 %.632619621.2, 8
  %sunkaddr1474 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1473
  %sunkaddr1475 = getelementptr i8, ptr %sunkaddr1474, i64 8
  %.691.2.1 = load double, ptr %sunkaddr1475, align 8
  %308 = shl i64 %.632619621.2, 3
  %scevgep547 = getelementptr i8, ptr %scevgep1168, i64 %308
  %scevgep548 = getelementptr i8, ptr %scevgep547, i64 -48
  %.720.2.1 = load double, ptr %scevgep548, align 8
  %.722.2.1 = fmul double %arg.h, %.720.2.1
  %.723.2.1 = fadd double %.691.2.1, %.722.2.1
  %sunkaddr1476 = mul i64 %.632619621.2, 8
  %sunkaddr1477 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1476
  %sunkaddr1478 = getelementptr i8, ptr %sunkaddr1477, i64 8
  store double %.723.2.1, ptr %sunkaddr1478, align 8
  %sunkaddr1479 = mul i64 %.632619621.2, 8
  %sunkaddr1480 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1479
  %sunkaddr1481 = getelementptr i8, ptr %sunkaddr1480, i64 16
  %.691.2.2 = load double, ptr %sunkaddr1481, align 8
  %309 = shl i64 %.632619621.2, 3
  %scevgep545 = getelementptr i8, ptr %scevgep1168, i64 %309
  %scevgep546 = getelementptr i8, ptr %scevgep545, i64 -40
  %.720.2.2 = load double, ptr %scevgep546, align 8
  %.722.2.2 = fmul double %arg.h, %.720.2.2
  %.723.2.2 = fadd double %.691.2.2, %.722.2.2
  %sunkaddr1482 = mul i64 %.632619621.2, 8
  %sunkaddr1483 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1482
  %sunkaddr1484 = getelementptr i8, ptr %sunkaddr1483, i64 16
  store double %.723.2.2, ptr %sunkaddr1484, align 8
  %sunkaddr1485 = mul i64 %.632619621.2, 8
  %sunkaddr1486 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1485
  %sunkaddr1487 = getelementptr i8, ptr %sunkaddr1486, i64 24
  %.691.2.3 = load double, ptr %sunkaddr1487, align 8
  %310 = shl i64 %.632619621.2, 3
  %scevgep543 = getelementptr i8, ptr %scevgep1168, i64 %310
  %scevgep544 = getelementptr i8, ptr %scevgep543, i64 -32
  %.720.2.3 = load double, ptr %scevgep544, align 8
  %.722.2.3 = fmul double %arg.h, %.720.2.3
  %.723.2.3 = fadd double %.691.2.3, %.722.2.3
  %sunkaddr1488 = mul i64 %.632619621.2, 8
  %sunkaddr1489 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1488
  %sunkaddr1490 = getelementptr i8, ptr %sunkaddr1489, i64 24
  store double %.723.2.3, ptr %sunkaddr1490, align 8
  %sunkaddr1491 = mul i64 %.632619621.2, 8
  %sunkaddr1492 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1491
  %sunkaddr1493 = getelementptr i8, ptr %sunkaddr1492, i64 32
  %.691.2.4 = load double, ptr %sunkaddr1493, align 8
  %311 = shl i64 %.632619621.2, 3
  %scevgep541 = getelementptr i8, ptr %scevgep1168, i64 %311
  %scevgep542 = getelementptr i8, ptr %scevgep541, i64 -24
  %.720.2.4 = load double, ptr %scevgep542, align 8
  %.722.2.4 = fmul double %arg.h, %.720.2.4
  %.723.2.4 = fadd double %.691.2.4, %.722.2.4
  %sunkaddr1494 = mul i64 %.632619621.2, 8
  %sunkaddr1495 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1494
  %sunkaddr1496 = getelementptr i8, ptr %sunkaddr1495, i64 32
  store double %.723.2.4, ptr %sunkaddr1496, align 8
  %sunkaddr1497 = mul i64 %.632619621.2, 8
  %sunkaddr1498 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1497
  %sunkaddr1499 = getelementptr i8, ptr %sunkaddr1498, i64 40
  %.691.2.5 = load double, ptr %sunkaddr1499, align 8
  %312 = shl i64 %.632619621.2, 3
  %scevgep539 = getelementptr i8, ptr %scevgep1168, i64 %312
  %scevgep540 = getelementptr i8, ptr %scevgep539, i64 -16
  %.720.2.5 = load double, ptr %scevgep540, align 8
  %.722.2.5 = fmul double %arg.h, %.720.2.5
  %.723.2.5 = fadd double %.691.2.5, %.722.2.5
  %sunkaddr1500 = mul i64 %.632619621.2, 8
  %sunkaddr1501 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1500
  %sunkaddr1502 = getelementptr i8, ptr %sunkaddr1501, i64 40
  store double %.723.2.5, ptr %sunkaddr1502, align 8
  %sunkaddr1503 = mul i64 %.632619621.2, 8
  %sunkaddr1504 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1503
  %sunkaddr1505 = getelementptr i8, ptr %sunkaddr1504, i64 48
  %.691.2.6 = load double, ptr %sunkaddr1505, align 8
  %313 = shl i64 %.632619621.2, 3
  %scevgep537 = getelementptr i8, ptr %scevgep1168, i64 %313
  %scevgep538 = getelementptr i8, ptr %scevgep537, i64 -8
  %.720.2.6 = load double, ptr %scevgep538, align 8
  %.722.2.6 = fmul double %arg.h, %.720.2.6
  %.723.2.6 = fadd double %.691.2.6, %.722.2.6
  %sunkaddr1506 = mul i64 %.632619621.2, 8
  %sunkaddr1507 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1506
  %sunkaddr1508 = getelementptr i8, ptr %sunkaddr1507, i64 48
  store double %.723.2.6, ptr %sunkaddr1508, align 8
  %.639.2.7 = add nuw nsw i64 %.632619621.2, 8
  %sunkaddr1509 = mul i64 %.632619621.2, 8
  %sunkaddr1510 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1509
  %sunkaddr1511 = getelementptr i8, ptr %sunkaddr1510, i64 56
  %.691.2.7 = load double, ptr %sunkaddr1511, align 8
  %.720.2.7 = load double, ptr %scevgep1180, align 8
  %.722.2.7 = fmul double %arg.h, %.720.2.7
  %.723.2.7 = fadd double %.691.2.7, %.722.2.7
  %sunkaddr1512 = mul i64 %.632619621.2, 8
  %sunkaddr1513 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr1512
  %sunkaddr1514 = getelementptr i8, ptr %sunkaddr1513, i64 56
  store double %.723.2.7, ptr %sunkaddr1514, align 8
  %exitcond.2.not.7 = icmp eq i64 %arg.y.2, %.639.2.7
  br i1 %exitcond.2.not.7, label %B13409637.2, label %B13409633.2, !llvm.loop !58

B13409637.2:                                      ; preds = %B13409633.2, %B13409633.2.prol.loopexit, %vec.epilog.middle.block132, %middle.block116, %B13409637.endif.endif.1
  %.806.2.idx = mul i64 %arg.K.5.1, 24
  %.806.2 = getelementptr i8, ptr %arg.K.4, i64 %.806.2.idx
  store double 0.000000e+00, ptr %.889, align 8
  %.899.2 = call i32 %arg.f.2(ptr nonnull %.889, ptr nonnull %excinfo.3, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.806.2, i64 %arg.K.5.1, i64 %arg.K.6.1)
  switch i32 %.899.2, label %B13409637.else.if.if [
    i32 -2, label %B13409637.endif.2
    i32 0, label %B13409637.endif.2
  ], !prof !4

B13409637.endif.2:                                ; preds = %B13409637.2, %B13409637.2
  %.909.2 = load double, ptr %.889, align 8
  %.10.i15 = fcmp olt double %.909.2, %.11.i14
  %.11.i16 = select i1 %.10.i15, double %.909.2, double %.11.i14
  br label %B13409639.endif

B13409639.endif:                                  ; preds = %B13409637.endif.2, %B13409637.us.2, %B13409637.if.if.endif.us.us.2
  %.925.0 = phi double [ %.11.i10, %B13409637.us.2 ], [ %.11.i4, %B13409637.if.if.endif.us.us.2 ], [ %.11.i16, %B13409637.endif.2 ]
  %314 = icmp slt i64 %arg.y.2, 1
  %.999 = fmul double %arg.h, 0x3FC5555555555555
  br i1 %314, label %B13409755, label %iter.check425

iter.check425:                                    ; preds = %B13409639.endif
  %315 = getelementptr double, ptr %.172, i64 %arg.y.2
  %.idx = shl i64 %arg.y.2, 4
  %316 = getelementptr i8, ptr %.172, i64 %.idx
  %.idx612 = mul i64 %arg.y.2, 24
  %317 = getelementptr i8, ptr %.172, i64 %.idx612
  %min.iters.check423 = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check423, label %B13409681.preheader, label %vector.memcheck411

vector.memcheck411:                               ; preds = %iter.check425
  %318 = ptrtoint ptr %.172 to i64
  %319 = ptrtoint ptr %arg.ynew.4 to i64
  %320 = ptrtoint ptr %arg.y.4 to i64
  %321 = sub i64 %319, %320
  %diff.check414 = icmp ult i64 %321, 256
  %322 = sub i64 %319, %318
  %323 = sub i64 %322, %.idx612
  %diff.check415 = icmp ult i64 %323, 256
  %conflict.rdx416 = or i1 %diff.check414, %diff.check415
  %324 = sub i64 %322, %.idx
  %diff.check417 = icmp ult i64 %324, 256
  %conflict.rdx418 = or i1 %diff.check417, %conflict.rdx416
  %325 = shl i64 %arg.y.2, 3
  %326 = sub i64 %322, %325
  %diff.check419 = icmp ult i64 %326, 256
  %conflict.rdx420 = or i1 %diff.check419, %conflict.rdx418
  %diff.check421 = icmp ult i64 %322, 256
  %conflict.rdx422 = or i1 %diff.check421, %conflict.rdx420
  br i1 %conflict.rdx422, label %B13409681.preheader, label %vector.main.loop.iter.check427

vector.main.loop.iter.check427:                   ; preds = %vector.memcheck411
  %const754 = bitcast i64 9223372036854775776 to i64
  %min.iters.check426 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check426, label %vec.epilog.ph462, label %vector.ph428

vector.ph428:                                     ; preds = %vector.main.loop.iter.check427
  %n.vec430 = and i64 %arg.y.2, %const754
  %broadcast.splatinsert431 = insertelement <8 x double> poison, double %.999, i64 0
  %broadcast.splat432 = shufflevector <8 x double> %broadcast.splatinsert431, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body433

vector.body433:                                   ; preds = %vector.body433, %vector.ph428
  %index434 = phi i64 [ 0, %vector.ph428 ], [ %index.next455, %vector.body433 ]
  %sunkaddr1515 = mul i64 %index434, 8
  %sunkaddr1516 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1515
  %wide.load435 = load <8 x double>, ptr %sunkaddr1516, align 8
  %sunkaddr1517 = mul i64 %index434, 8
  %sunkaddr1518 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1517
  %sunkaddr1519 = getelementptr i8, ptr %sunkaddr1518, i64 64
  %wide.load436 = load <8 x double>, ptr %sunkaddr1519, align 8
  %sunkaddr1520 = mul i64 %index434, 8
  %sunkaddr1521 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1520
  %sunkaddr1522 = getelementptr i8, ptr %sunkaddr1521, i64 128
  %wide.load437 = load <8 x double>, ptr %sunkaddr1522, align 8
  %sunkaddr1523 = mul i64 %index434, 8
  %sunkaddr1524 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr1523
  %sunkaddr1525 = getelementptr i8, ptr %sunkaddr1524, i64 192
  %wide.load438 = load <8 x double>, ptr %sunkaddr1525, align 8
  %327 = shl i64 %index434, 3
  %scevgep85 = getelementptr i8, ptr %.172, i64 %327
  %wide.load439 = load <8 x double>, ptr %scevgep85, align 8
  %scevgep94 = getelementptr i8, ptr %scevgep85, i64 64
  %wide.load440 = load <8 x double>, ptr %scevgep94, align 8
  %scevgep95 = getelementptr i8, ptr %scevgep85, i64 128
  %wide.load441 = load <8 x double>, ptr %scevgep95, align 8
  %scevgep96 = getelementptr i8, ptr %scevgep85, i64 192
  %wide.load442 = load <8 x double>, ptr %scevgep96, align 8
  %scevgep97 = getelementptr i8, ptr %scevgep85, i64 %325
  %wide.load443 = load <8 x double>, ptr %scevgep97, align 8
  %scevgep98 = getelementptr i8, ptr %scevgep97, i64 64
  %wide.load444 = load <8 x double>, ptr %scevgep98, align 8
  %scevgep99 = getelementptr i8, ptr %scevgep97, i64 128
  %wide.load445 = load <8 x double>, ptr %scevgep99, align 8
  %scevgep100 = getelementptr i8, ptr %scevgep97, i64 192
  %wide.load446 = load <8 x double>, ptr %scevgep100, align 8
  %scevgep101 = getelementptr i8, ptr %scevgep97, i64 %325
  %wide.load447 = load <8 x double>, ptr %scevgep101, align 8
  %scevgep102 = getelementptr i8, ptr %scevgep101, i64 64
  %wide.load448 = load <8 x double>, ptr %scevgep102, align 8
  %scevgep103 = getelementptr i8, ptr %scevgep101, i64 128
  %wide.load449 = load <8 x double>, ptr %scevgep103, align 8
  %scevgep104 = getelementptr i8, ptr %scevgep101, i64 192
  %wide.load450 = load <8 x double>, ptr %scevgep104, align 8
  %scevgep105 = getelementptr i8, ptr %scevgep101, i64 %325
  %wide.load451 = load <8 x double>, ptr %scevgep105, align 8
  %scevgep106 = getelementptr i8, ptr %scevgep105, i64 64
  %wide.load452 = load <8 x double>, ptr %scevgep106, align 8
  %scevgep107 = getelementptr i8, ptr %scevgep105, i64 128
  %wide.load453 = load <8 x double>, ptr %scevgep107, align 8
  %scevgep108 = getelementptr i8, ptr %scevgep105, i64 192
  %wide.load454 = load <8 x double>, ptr %scevgep108, align 8
  %328 = fmul <8 x double> %wide.load443, splat (double 2.000000e+00)
  %329 = fmul <8 x double> %wide.load444, splat (double 2.000000e+00)
  %330 = fmul <8 x double> %wide.load445, splat (double 2.000000e+00)
  %331 = fmul <8 x double> %wide.load446, splat (double 2.000000e+00)
  %332 = fadd <8 x double> %wide.load439, %328
  %333 = fadd <8 x double> %wide.load440, %329
  %334 = fadd <8 x double> %wide.load441, %330
  %335 = fadd <8 x double> %wide.load442, %331
  %336 = fmul <8 x double> %wide.load447, splat (double 2.000000e+00)
  %337 = fmul <8 x double> %wide.load448, splat (double 2.000000e+00)
  %338 = fmul <8 x double> %wide.load449, splat (double 2.000000e+00)
  %339 = fmul <8 x double> %wide.load450, splat (double 2.000000e+00)
  %340 = fadd <8 x double> %332, %336
  %341 = fadd <8 x double> %333, %337
  %342 = fadd <8 x double> %334, %338
  %343 = fadd <8 x double> %335, %339
  %344 = fadd <8 x double> %340, %wide.load451
  %345 = fadd <8 x double> %341, %wide.load452
  %346 = fadd <8 x double> %342, %wide.load453
  %347 = fadd <8 x double> %343, %wide.load454
  %348 = fmul <8 x double> %broadcast.splat432, %344
  %349 = fmul <8 x double> %broadcast.splat432, %345
  %350 = fmul <8 x double> %broadcast.splat432, %346
  %351 = fmul <8 x double> %broadcast.splat432, %347
  %352 = fadd <8 x double> %wide.load435, %348
  %353 = fadd <8 x double> %wide.load436, %349
  %354 = fadd <8 x double> %wide.load437, %350
  %355 = fadd <8 x double> %wide.load438, %351
  %sunkaddr1526 = mul i64 %index434, 8
  %sunkaddr1527 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1526
  store <8 x double> %352, ptr %sunkaddr1527, align 8
  %sunkaddr1528 = mul i64 %index434, 8
  %sunkaddr1529 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1528
  %sunkaddr1530 = getelementptr i8, ptr %sunkaddr1529, i64 64
  store <8 x double> %353, ptr %sunkaddr1530, align 8
  %sunkaddr1531 = mul i64 %index434, 8
  %sunkaddr1532 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1531
  %sunkaddr1533 = getelementptr i8, ptr %sunkaddr1532, i64 128
  store <8 x double> %354, ptr %sunkaddr1533, align 8
  %sunkaddr1534 = mul i64 %index434, 8
  %sunkaddr1535 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr1534
  %sunkaddr1536 = getelementptr i8, ptr %sunkaddr1535, i64 192
  store <8 x double> %355, ptr %sunkaddr1536, align 8
  %index.next455 = add nuw nsw i64 %index434, 32
  %356 = icmp eq i64 %n.vec430, %index.next455
  br i1 %356, label %middle.block456, label %vector.body433, !llvm.loop !59

middle.block456:                                  ; preds = %vector.body433
  %cmp.n457 = icmp eq i64 %arg.y.2, %n.vec430
  br i1 %cmp.n457, label %B13409755, label %vec.epilog.iter.check460

vec.epilog.iter.check460:                         ; preds = %middle.block456
  %357 = and i64 %arg.y.2, 28
  %min.epilog.iters.check461 = icmp eq i64 %357, 0
  br i1 %min.epilog.iters.check461, label %B13409681.preheader, label %vec.epilog.ph462, !prof !9

vec.epilog.ph462:                                 ; preds = %vec.epilog.iter.check460, %vector.main.loop.iter.check427
  %vec.epilog.resume.val458 = phi i64 [ %n.vec430, %vec.epilog.iter.check460 ], [ 0, %vector.main.loop.iter.check427 ]
  %const_mat755 = add i64 %const754, 28
  %n.vec464 = and i64 %arg.y.2, %const_mat755
  %broadcast.splatinsert465 = insertelement <4 x double> poison, double %.999, i64 0
  %broadcast.splat466 = shufflevector <4 x double> %broadcast.splatinsert465, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body467

vec.epilog.vector.body467:                        ; preds = %vec.epilog.vector.body467, %vec.epilog.ph462
  %index468 = phi i64 [ %vec.epilog.resume.val458, %vec.epilog.ph462 ], [ %index.next474, %vec.epilog.vector.body467 ]
  %358 = shl i64 %index468, 3
  %scevgep639 = getelementptr i8, ptr %arg.y.4, i64 %358
  %wide.load469 = load <4 x double>, ptr %scevgep639, align 8
  %scevgep638 = getelementptr i8, ptr %.172, i64 %358
  %wide.load470 = load <4 x double>, ptr %scevgep638, align 8
  %scevgep637 = getelementptr i8, ptr %315, i64 %358
  %wide.load471 = load <4 x double>, ptr %scevgep637, align 8
  %359 = shl i64 %index468, 3
  %scevgep76 = getelementptr i8, ptr %316, i64 %359
  %wide.load472 = load <4 x double>, ptr %scevgep76, align 8
  %360 = shl i64 %index468, 3
  %scevgep75 = getelementptr i8, ptr %317, i64 %360
  %wide.load473 = load <4 x double>, ptr %scevgep75, align 8
  %361 = fmul <4 x double> %wide.load471, splat (double 2.000000e+00)
  %362 = fadd <4 x double> %wide.load470, %361
  %363 = fmul <4 x double> %wide.load472, splat (double 2.000000e+00)
  %364 = fadd <4 x double> %362, %363
  %365 = fadd <4 x double> %wide.load473, %364
  %366 = fmul <4 x double> %broadcast.splat466, %365
  %367 = fadd <4 x double> %wide.load469, %366
  %368 = shl i64 %index468, 3
  %scevgep74 = getelementptr i8, ptr %arg.ynew.4, i64 %368
  store <4 x double> %367, ptr %scevgep74, align 8
  %index.next474 = add nuw i64 %index468, 4
  %369 = icmp eq i64 %n.vec464, %index.next474
  br i1 %369, label %vec.epilog.middle.block475, label %vec.epilog.vector.body467, !llvm.loop !60

vec.epilog.middle.block475:                       ; preds = %vec.epilog.vector.body467
  %cmp.n476 = icmp eq i64 %arg.y.2, %n.vec464
  br i1 %cmp.n476, label %B13409755, label %B13409681.preheader

B13409681.preheader:                              ; preds = %vec.epilog.middle.block475, %vec.epilog.iter.check460, %vector.memcheck411, %iter.check425
  %.1101668670.ph = phi i64 [ 0, %iter.check425 ], [ 0, %vector.memcheck411 ], [ %n.vec430, %vec.epilog.iter.check460 ], [ %n.vec464, %vec.epilog.middle.block475 ]
  %xtraiter562 = and i64 %arg.y.2, 3
  %lcmp.mod563.not = icmp eq i64 %xtraiter562, 0
  br i1 %lcmp.mod563.not, label %B13409681.prol.loopexit, label %B13409681.prol.preheader

B13409681.prol.preheader:                         ; preds = %B13409681.preheader
  %370 = shl i64 %.1101668670.ph, 3
  %scevgep622 = getelementptr i8, ptr %arg.ynew.4, i64 %370
  %scevgep624 = getelementptr i8, ptr %317, i64 %370
  %scevgep626 = getelementptr i8, ptr %316, i64 %370
  %371 = add nuw i64 %.1101668670.ph, %arg.y.2
  %372 = shl i64 %371, 3
  %scevgep628 = getelementptr i8, ptr %.172, i64 %372
  %scevgep630 = getelementptr i8, ptr %.172, i64 %370
  %scevgep632 = getelementptr i8, ptr %arg.y.4, i64 %370
  %373 = shl nuw nsw i64 %xtraiter562, 3
  br label %B13409681.prol

B13409681.prol:                                   ; preds = %B13409681.prol, %B13409681.prol.preheader
  %lsr.iv66 = phi i64 [ %lsr.iv.next67, %B13409681.prol ], [ 0, %B13409681.prol.preheader ]
  %scevgep73 = getelementptr i8, ptr %scevgep632, i64 %lsr.iv66
  %.1160.prol = load double, ptr %scevgep73, align 8
  %scevgep72 = getelementptr i8, ptr %scevgep630, i64 %lsr.iv66
  %.1187.prol = load double, ptr %scevgep72, align 8
  %scevgep71 = getelementptr i8, ptr %scevgep628, i64 %lsr.iv66
  %.1216.prol = load double, ptr %scevgep71, align 8
  %scevgep70 = getelementptr i8, ptr %scevgep626, i64 %lsr.iv66
  %.1245.prol = load double, ptr %scevgep70, align 8
  %scevgep69 = getelementptr i8, ptr %scevgep624, i64 %lsr.iv66
  %.1274.prol = load double, ptr %scevgep69, align 8
  %.1276.prol = fmul double %.1216.prol, 2.000000e+00
  %.1277.prol = fadd double %.1187.prol, %.1276.prol
  %.1278.prol = fmul double %.1245.prol, 2.000000e+00
  %.1279.prol = fadd double %.1277.prol, %.1278.prol
  %.1280.prol = fadd double %.1274.prol, %.1279.prol
  %.1281.prol = fmul double %.999, %.1280.prol
  %.1282.prol = fadd double %.1160.prol, %.1281.prol
  %scevgep68 = getelementptr i8, ptr %scevgep622, i64 %lsr.iv66
  store double %.1282.prol, ptr %scevgep68, align 8
  %lsr.iv.next67 = add nuw nsw i64 %lsr.iv66, 8
  %prol.iter564.cmp.not = icmp eq i64 %373, %lsr.iv.next67
  br i1 %prol.iter564.cmp.not, label %B13409681.prol.loopexit.loopexit, label %B13409681.prol, !llvm.loop !61

B13409681.prol.loopexit.loopexit:                 ; preds = %B13409681.prol
  %374 = or disjoint i64 %xtraiter562, %.1101668670.ph
  br label %B13409681.prol.loopexit

B13409681.prol.loopexit:                          ; preds = %B13409681.prol.loopexit.loopexit, %B13409681.preheader
  %.1101668670.unr = phi i64 [ %.1101668670.ph, %B13409681.preheader ], [ %374, %B13409681.prol.loopexit.loopexit ]
  %375 = sub nsw i64 %.1101668670.ph, %arg.y.2
  %376 = icmp ugt i64 %375, -4
  br i1 %376, label %B13409755, label %B13409681.preheader565

B13409681.preheader565:                           ; preds = %B13409681.prol.loopexit
  %377 = shl i64 %.1101668670.unr, 3
  %378 = add i64 %377, 24
  %scevgep = getelementptr i8, ptr %arg.ynew.4, i64 %378
  %379 = getelementptr i8, ptr %317, i64 %377
  %scevgep582 = getelementptr i8, ptr %379, i64 24
  %380 = getelementptr i8, ptr %316, i64 %377
  %scevgep590 = getelementptr i8, ptr %380, i64 24
  %381 = add nuw i64 %.1101668670.unr, %arg.y.2
  %382 = shl i64 %381, 3
  %383 = getelementptr i8, ptr %.172, i64 %382
  %scevgep598 = getelementptr i8, ptr %383, i64 24
  %scevgep614 = getelementptr i8, ptr %arg.y.4, i64 %378
  %384 = add i64 %.1101668670.ph, %xtraiter562
  %385 = sub i64 %arg.y.2, %384
  %386 = shl i64 %.1101668670.ph, 3
  %387 = shl nuw nsw i64 %xtraiter562, 3
  %388 = add i64 %386, %387
  %389 = add i64 %388, 24
  %scevgep54 = getelementptr i8, ptr %.172, i64 %389
  br label %B13409681
}

declare i32 @numba_attempt_nocopy_reshape(i64, ptr, ptr, i64, ptr, ptr, i64, i32) local_unnamed_addr

; Function Attrs: nofree norecurse nosync nounwind memory(argmem: readwrite)
define linkonce_odr noundef i32 @_ZN6charts7solvers2rk13hermite_denseB3v82B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias readnone captures(none) %excinfo, ptr readnone captures(none) %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr readnone captures(none) %arg.ynew.0, ptr readnone captures(none) %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr readonly captures(none) %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %arg.h, ptr readnone captures(none) %arg.f0.0, ptr readnone captures(none) %arg.f0.1, i64 %arg.f0.2, i64 %arg.f0.3, ptr readonly captures(none) %arg.f0.4, i64 %arg.f0.5.0, i64 %arg.f0.6.0, ptr readnone captures(none) %arg.f1.0, ptr readnone captures(none) %arg.f1.1, i64 %arg.f1.2, i64 %arg.f1.3, ptr readonly captures(none) %arg.f1.4, i64 %arg.f1.5.0, i64 %arg.f1.6.0, ptr readnone captures(none) %arg.F.0, ptr readnone captures(none) %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr writeonly captures(none) %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1) local_unnamed_addr #2 {
B0.endif:
  %.183 = icmp sgt i64 %arg.y.2, 0
  br i1 %.183, label %B88.lr.ph, label %B13409956

B88.lr.ph:                                        ; preds = %B0.endif
  %0 = getelementptr double, ptr %arg.F.4, i64 %arg.F.5.1
  %.idx = shl i64 %arg.F.5.1, 4
  %1 = getelementptr i8, ptr %arg.F.4, i64 %.idx
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 40
  br i1 %min.iters.check, label %B88.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %B88.lr.ph
  %2 = shl i64 %arg.y.2, 3
  %scevgep = getelementptr i8, ptr %arg.F.4, i64 %2
  %3 = add i64 %arg.F.5.1, %arg.y.2
  %4 = shl i64 %3, 3
  %scevgep2 = getelementptr i8, ptr %arg.F.4, i64 %4
  %scevgep3 = getelementptr i8, ptr %1, i64 %2
  %scevgep4 = getelementptr i8, ptr %arg.ynew.4, i64 %2
  %scevgep5 = getelementptr i8, ptr %arg.y.4, i64 %2
  %scevgep6 = getelementptr i8, ptr %arg.f0.4, i64 %2
  %scevgep7 = getelementptr i8, ptr %arg.f1.4, i64 %2
  %bound0 = icmp ult ptr %arg.F.4, %scevgep2
  %bound1 = icmp ult ptr %0, %scevgep
  %found.conflict = and i1 %bound1, %bound0
  %bound08 = icmp ult ptr %arg.F.4, %scevgep3
  %bound19 = icmp ult ptr %1, %scevgep
  %found.conflict10 = and i1 %bound19, %bound08
  %conflict.rdx = or i1 %found.conflict, %found.conflict10
  %bound011 = icmp ult ptr %arg.F.4, %scevgep4
  %bound112 = icmp ult ptr %arg.ynew.4, %scevgep
  %found.conflict13 = and i1 %bound011, %bound112
  %conflict.rdx14 = or i1 %found.conflict13, %conflict.rdx
  %bound015 = icmp ult ptr %arg.F.4, %scevgep5
  %bound116 = icmp ult ptr %arg.y.4, %scevgep
  %found.conflict17 = and i1 %bound015, %bound116
  %conflict.rdx18 = or i1 %found.conflict17, %conflict.rdx14
  %bound019 = icmp ult ptr %arg.F.4, %scevgep6
  %bound120 = icmp ult ptr %arg.f0.4, %scevgep
  %found.conflict21 = and i1 %bound019, %bound120
  %conflict.rdx22 = or i1 %found.conflict21, %conflict.rdx18
  %bound023 = icmp ult ptr %arg.F.4, %scevgep7
  %bound124 = icmp ult ptr %arg.f1.4, %scevgep
  %found.conflict25 = and i1 %bound023, %bound124
  %conflict.rdx26 = or i1 %found.conflict25, %conflict.rdx22
  %bound027 = icmp ult ptr %0, %scevgep3
  %bound128 = icmp ult ptr %1, %scevgep2
  %found.conflict29 = and i1 %bound027, %bound128
  %conflict.rdx30 = or i1 %found.conflict29, %conflict.rdx26
  %bound031 = icmp ult ptr %0, %scevgep4
  %bound132 = icmp ult ptr %arg.ynew.4, %scevgep2
  %found.conflict33 = and i1 %bound031, %bound132
  %conflict.rdx34 = or i1 %found.conflict33, %conflict.rdx30
  %bound035 = icmp ult ptr %0, %scevgep5
  %bound136 = icmp ult ptr %arg.y.4, %scevgep2
  %found.conflict37 = and i1 %bound035, %bound136
  %conflict.rdx38 = or i1 %found.conflict37, %conflict.rdx34
  %bound039 = icmp ult ptr %0, %scevgep6
  %bound140 = icmp ult ptr %arg.f0.4, %scevgep2
  %found.conflict41 = and i1 %bound039, %bound140
  %conflict.rdx42 = or i1 %found.conflict41, %conflict.rdx38
  %bound043 = icmp ult ptr %0, %scevgep7
  %bound144 = icmp ult ptr %arg.f1.4, %scevgep2
  %found.conflict45 = and i1 %bound043, %bound144
  %conflict.rdx46 = or i1 %found.conflict45, %conflict.rdx42
  %bound047 = icmp ult ptr %1, %scevgep4
  %bound148 = icmp ult ptr %arg.ynew.4, %scevgep3
  %found.conflict49 = and i1 %bound047, %bound148
  %conflict.rdx50 = or i1 %found.conflict49, %conflict.rdx46
  %bound051 = icmp ult ptr %1, %scevgep5
  %bound152 = icmp ult ptr %arg.y.4, %scevgep3
  %found.conflict53 = and i1 %bound051, %bound152
  %conflict.rdx54 = or i1 %found.conflict53, %conflict.rdx50
  %bound055 = icmp ult ptr %1, %scevgep6
  %bound156 = icmp ult ptr %arg.f0.4, %scevgep3
  %found.conflict57 = and i1 %bound055, %bound156
  %conflict.rdx58 = or i1 %found.conflict57, %conflict.rdx54
  %bound059 = icmp ult ptr %1, %scevgep7
  %bound160 = icmp ult ptr %arg.f1.4, %scevgep3
  %found.conflict61 = and i1 %bound059, %bound160
  %conflict.rdx62 = or i1 %found.conflict61, %conflict.rdx58
  br i1 %conflict.rdx62, label %B88.preheader, label %vector.ph

vector.ph:                                        ; preds = %vector.memcheck
  %n.vec = and i64 %arg.y.2, 9223372036854775800
  %broadcast.splatinsert = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %5 = shl i64 %index, 3
  %scevgep144 = getelementptr i8, ptr %arg.ynew.4, i64 %5
  %wide.load = load <8 x double>, ptr %scevgep144, align 8, !alias.scope !62
  %scevgep143 = getelementptr i8, ptr %arg.y.4, i64 %5
  %wide.load63 = load <8 x double>, ptr %scevgep143, align 8, !alias.scope !65
  %6 = fsub <8 x double> %wide.load, %wide.load63
  %7 = shl i64 %index, 3
  %scevgep59 = getelementptr i8, ptr %arg.F.4, i64 %7
  store <8 x double> %6, ptr %scevgep59, align 8, !alias.scope !67, !noalias !69
  %8 = shl i64 %index, 3
  %scevgep58 = getelementptr i8, ptr %arg.f0.4, i64 %8
  %wide.load64 = load <8 x double>, ptr %scevgep58, align 8, !alias.scope !74
  %9 = fmul <8 x double> %broadcast.splat, %wide.load64
  %10 = fsub <8 x double> %9, %6
  %11 = shl i64 %index, 3
  %scevgep57 = getelementptr i8, ptr %0, i64 %11
  store <8 x double> %10, ptr %scevgep57, align 8, !alias.scope !75, !noalias !76
  %12 = fmul <8 x double> %6, splat (double 2.000000e+00)
  %13 = shl i64 %index, 3
  %scevgep56 = getelementptr i8, ptr %arg.f1.4, i64 %13
  %wide.load65 = load <8 x double>, ptr %scevgep56, align 8, !alias.scope !77
  %14 = fadd <8 x double> %wide.load64, %wide.load65
  %15 = fmul <8 x double> %broadcast.splat, %14
  %16 = fsub <8 x double> %12, %15
  %17 = shl i64 %index, 3
  %scevgep55 = getelementptr i8, ptr %1, i64 %17
  store <8 x double> %16, ptr %scevgep55, align 8, !alias.scope !78, !noalias !79
  %index.next = add nuw nsw i64 %index, 8
  %18 = icmp eq i64 %n.vec, %index.next
  br i1 %18, label %middle.block, label %vector.body, !llvm.loop !80

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B150.endif.us.preheader, label %B88.preheader

B88.preheader:                                    ; preds = %middle.block, %vector.memcheck, %B88.lr.ph
  %.233367369.ph = phi i64 [ 0, %vector.memcheck ], [ 0, %B88.lr.ph ], [ %n.vec, %middle.block ]
  %xtraiter = and i64 %arg.y.2, 3
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B88.prol.loopexit, label %B88.prol.preheader

B88.prol.preheader:                               ; preds = %B88.preheader
  %19 = shl i64 %.233367369.ph, 3
  %scevgep124 = getelementptr i8, ptr %1, i64 %19
  %scevgep126 = getelementptr i8, ptr %arg.f1.4, i64 %19
  %20 = add i64 %.233367369.ph, %arg.F.5.1
  %21 = shl i64 %20, 3
  %scevgep128 = getelementptr i8, ptr %arg.F.4, i64 %21
  %scevgep130 = getelementptr i8, ptr %arg.f0.4, i64 %19
  %scevgep132 = getelementptr i8, ptr %arg.F.4, i64 %19
  %scevgep134 = getelementptr i8, ptr %arg.y.4, i64 %19
  %scevgep136 = getelementptr i8, ptr %arg.ynew.4, i64 %19
  %22 = shl nuw nsw i64 %xtraiter, 3
  br label %B88.prol

B88.prol:                                         ; preds = %B88.prol, %B88.prol.preheader
  %lsr.iv46 = phi i64 [ %lsr.iv.next47, %B88.prol ], [ 0, %B88.prol.preheader ]
  %scevgep54 = getelementptr i8, ptr %scevgep136, i64 %lsr.iv46
  %.294.prol = load double, ptr %scevgep54, align 8
  %scevgep53 = getelementptr i8, ptr %scevgep134, i64 %lsr.iv46
  %.324.prol = load double, ptr %scevgep53, align 8
  %.325.prol = fsub double %.294.prol, %.324.prol
  %scevgep52 = getelementptr i8, ptr %scevgep132, i64 %lsr.iv46
  store double %.325.prol, ptr %scevgep52, align 8
  %scevgep51 = getelementptr i8, ptr %scevgep130, i64 %lsr.iv46
  %.409.prol = load double, ptr %scevgep51, align 8
  %.411.prol = fmul double %arg.h, %.409.prol
  %.412.prol = fsub double %.411.prol, %.325.prol
  %scevgep50 = getelementptr i8, ptr %scevgep128, i64 %lsr.iv46
  store double %.412.prol, ptr %scevgep50, align 8
  %.467.prol = fmul double %.325.prol, 2.000000e+00
  %scevgep49 = getelementptr i8, ptr %scevgep126, i64 %lsr.iv46
  %.497.prol = load double, ptr %scevgep49, align 8
  %.527.prol = load double, ptr %scevgep51, align 8
  %.528.prol = fadd double %.497.prol, %.527.prol
  %.530.prol = fmul double %arg.h, %.528.prol
  %.531.prol = fsub double %.467.prol, %.530.prol
  %scevgep48 = getelementptr i8, ptr %scevgep124, i64 %lsr.iv46
  store double %.531.prol, ptr %scevgep48, align 8
  %lsr.iv.next47 = add nuw nsw i64 %lsr.iv46, 8
  %prol.iter.cmp.not = icmp eq i64 %22, %lsr.iv.next47
  br i1 %prol.iter.cmp.not, label %B88.prol.loopexit.loopexit, label %B88.prol, !llvm.loop !81

B88.prol.loopexit.loopexit:                       ; preds = %B88.prol
  %23 = or disjoint i64 %xtraiter, %.233367369.ph
  br label %B88.prol.loopexit

B88.prol.loopexit:                                ; preds = %B88.prol.loopexit.loopexit, %B88.preheader
  %.233367369.unr = phi i64 [ %.233367369.ph, %B88.preheader ], [ %23, %B88.prol.loopexit.loopexit ]
  %24 = sub nsw i64 %.233367369.ph, %arg.y.2
  %25 = icmp ugt i64 %24, -4
  br i1 %25, label %B150.endif.us.preheader, label %B88.preheader67

B88.preheader67:                                  ; preds = %B88.prol.loopexit
  %26 = shl i64 %.233367369.unr, 3
  %27 = getelementptr i8, ptr %1, i64 %26
  %scevgep68 = getelementptr i8, ptr %27, i64 24
  %28 = add i64 %26, 24
  %scevgep76 = getelementptr i8, ptr %arg.f1.4, i64 %28
  %29 = add i64 %.233367369.unr, %arg.F.5.1
  %30 = shl i64 %29, 3
  %31 = getelementptr i8, ptr %arg.F.4, i64 %30
  %scevgep84 = getelementptr i8, ptr %31, i64 24
  %scevgep92 = getelementptr i8, ptr %arg.f0.4, i64 %28
  %scevgep108 = getelementptr i8, ptr %arg.y.4, i64 %28
  %scevgep116 = getelementptr i8, ptr %arg.ynew.4, i64 %28
  %32 = add i64 %.233367369.ph, %xtraiter
  %33 = sub i64 %arg.y.2, %32
  %34 = shl i64 %.233367369.ph, 3
  %35 = shl nuw nsw i64 %xtraiter, 3
  %36 = add i64 %34, %35
  %37 = add i64 %36, 24
  %scevgep31 = getelementptr i8, ptr %arg.F.4, i64 %37
  br label %B88

B88:                                              ; preds = %B88, %B88.preheader67
  %lsr.iv = phi i64 [ 0, %B88.preheader67 ], [ %lsr.iv.next, %B88 ]
  %38 = shl i64 %lsr.iv, 3
  %scevgep120 = getelementptr i8, ptr %scevgep116, i64 %38
  %scevgep121 = getelementptr i8, ptr %scevgep120, i64 -24
  %.294 = load double, ptr %scevgep121, align 8
  %scevgep112 = getelementptr i8, ptr %scevgep108, i64 %38
  %scevgep113 = getelementptr i8, ptr %scevgep112, i64 -24
  %.324 = load double, ptr %scevgep113, align 8
  %.325 = fsub double %.294, %.324
  %39 = shl i64 %lsr.iv, 3
  %scevgep32 = getelementptr i8, ptr %scevgep31, i64 %39
  %scevgep37 = getelementptr i8, ptr %scevgep32, i64 -24
  store double %.325, ptr %scevgep37, align 8
  %40 = shl i64 %lsr.iv, 3
  %scevgep25 = getelementptr i8, ptr %scevgep92, i64 %40
  %scevgep30 = getelementptr i8, ptr %scevgep25, i64 -24
  %.409 = load double, ptr %scevgep30, align 8
  %.411 = fmul double %arg.h, %.409
  %.412 = fsub double %.411, %.325
  %41 = shl i64 %lsr.iv, 3
  %scevgep19 = getelementptr i8, ptr %scevgep84, i64 %41
  %scevgep24 = getelementptr i8, ptr %scevgep19, i64 -24
  store double %.412, ptr %scevgep24, align 8
  %.467 = fmul double %.325, 2.000000e+00
  %42 = shl i64 %lsr.iv, 3
  %scevgep13 = getelementptr i8, ptr %scevgep76, i64 %42
  %scevgep18 = getelementptr i8, ptr %scevgep13, i64 -24
  %.497 = load double, ptr %scevgep18, align 8
  %.527 = load double, ptr %scevgep30, align 8
  %.528 = fadd double %.497, %.527
  %.530 = fmul double %arg.h, %.528
  %.531 = fsub double %.467, %.530
  %43 = shl i64 %lsr.iv, 3
  %scevgep1 = getelementptr i8, ptr %scevgep68, i64 %43
  %scevgep12 = getelementptr i8, ptr %scevgep1, i64 -24
  store double %.531, ptr %scevgep12, align 8
  %scevgep44 = getelementptr i8, ptr %scevgep116, i64 %43
  %scevgep45 = getelementptr i8, ptr %scevgep44, i64 -16
  %.294.1 = load double, ptr %scevgep45, align 8
  %44 = shl i64 %lsr.iv, 3
  %scevgep40 = getelementptr i8, ptr %scevgep108, i64 %44
  %scevgep41 = getelementptr i8, ptr %scevgep40, i64 -16
  %.324.1 = load double, ptr %scevgep41, align 8
  %.325.1 = fsub double %.294.1, %.324.1
  %45 = shl i64 %lsr.iv, 3
  %scevgep35 = getelementptr i8, ptr %scevgep31, i64 %45
  %scevgep36 = getelementptr i8, ptr %scevgep35, i64 -16
  store double %.325.1, ptr %scevgep36, align 8
  %46 = shl i64 %lsr.iv, 3
  %scevgep28 = getelementptr i8, ptr %scevgep92, i64 %46
  %scevgep29 = getelementptr i8, ptr %scevgep28, i64 -16
  %.409.1 = load double, ptr %scevgep29, align 8
  %.411.1 = fmul double %arg.h, %.409.1
  %.412.1 = fsub double %.411.1, %.325.1
  %47 = shl i64 %lsr.iv, 3
  %scevgep22 = getelementptr i8, ptr %scevgep84, i64 %47
  %scevgep23 = getelementptr i8, ptr %scevgep22, i64 -16
  store double %.412.1, ptr %scevgep23, align 8
  %.467.1 = fmul double %.325.1, 2.000000e+00
  %48 = shl i64 %lsr.iv, 3
  %scevgep16 = getelementptr i8, ptr %scevgep76, i64 %48
  %scevgep17 = getelementptr i8, ptr %scevgep16, i64 -16
  %.497.1 = load double, ptr %scevgep17, align 8
  %.527.1 = load double, ptr %scevgep29, align 8
  %.528.1 = fadd double %.497.1, %.527.1
  %.530.1 = fmul double %arg.h, %.528.1
  %.531.1 = fsub double %.467.1, %.530.1
  %49 = shl i64 %lsr.iv, 3
  %scevgep10 = getelementptr i8, ptr %scevgep68, i64 %49
  %scevgep11 = getelementptr i8, ptr %scevgep10, i64 -16
  store double %.531.1, ptr %scevgep11, align 8
  %scevgep42 = getelementptr i8, ptr %scevgep116, i64 %49
  %scevgep43 = getelementptr i8, ptr %scevgep42, i64 -8
  %.294.2 = load double, ptr %scevgep43, align 8
  %50 = shl i64 %lsr.iv, 3
  %scevgep38 = getelementptr i8, ptr %scevgep108, i64 %50
  %scevgep39 = getelementptr i8, ptr %scevgep38, i64 -8
  %.324.2 = load double, ptr %scevgep39, align 8
  %.325.2 = fsub double %.294.2, %.324.2
  %51 = shl i64 %lsr.iv, 3
  %scevgep33 = getelementptr i8, ptr %scevgep31, i64 %51
  %scevgep34 = getelementptr i8, ptr %scevgep33, i64 -8
  store double %.325.2, ptr %scevgep34, align 8
  %52 = shl i64 %lsr.iv, 3
  %scevgep26 = getelementptr i8, ptr %scevgep92, i64 %52
  %scevgep27 = getelementptr i8, ptr %scevgep26, i64 -8
  %.409.2 = load double, ptr %scevgep27, align 8
  %.411.2 = fmul double %arg.h, %.409.2
  %.412.2 = fsub double %.411.2, %.325.2
  %53 = shl i64 %lsr.iv, 3
  %scevgep20 = getelementptr i8, ptr %scevgep84, i64 %53
  %scevgep21 = getelementptr i8, ptr %scevgep20, i64 -8
  store double %.412.2, ptr %scevgep21, align 8
  %.467.2 = fmul double %.325.2, 2.000000e+00
  %54 = shl i64 %lsr.iv, 3
  %scevgep14 = getelementptr i8, ptr %scevgep76, i64 %54
  %scevgep15 = getelementptr i8, ptr %scevgep14, i64 -8
  %.497.2 = load double, ptr %scevgep15, align 8
  %.527.2 = load double, ptr %scevgep27, align 8
  %.528.2 = fadd double %.497.2, %.527.2
  %.530.2 = fmul double %arg.h, %.528.2
  %.531.2 = fsub double %.467.2, %.530.2
  %55 = shl i64 %lsr.iv, 3
  %scevgep8 = getelementptr i8, ptr %scevgep68, i64 %55
  %scevgep9 = getelementptr i8, ptr %scevgep8, i64 -8
  store double %.531.2, ptr %scevgep9, align 8
  %.294.3 = load double, ptr %scevgep120, align 8
  %.324.3 = load double, ptr %scevgep112, align 8
  %.325.3 = fsub double %.294.3, %.324.3
  store double %.325.3, ptr %scevgep32, align 8
  %.409.3 = load double, ptr %scevgep25, align 8
  %.411.3 = fmul double %arg.h, %.409.3
  %.412.3 = fsub double %.411.3, %.325.3
  store double %.412.3, ptr %scevgep19, align 8
  %.467.3 = fmul double %.325.3, 2.000000e+00
  %.497.3 = load double, ptr %scevgep13, align 8
  %.527.3 = load double, ptr %scevgep25, align 8
  %.528.3 = fadd double %.497.3, %.527.3
  %.530.3 = fmul double %arg.h, %.528.3
  %.531.3 = fsub double %.467.3, %.530.3
  store double %.531.3, ptr %scevgep1, align 8
  %lsr.iv.next = add i64 %lsr.iv, 4
  %exitcond.not.3 = icmp eq i64 %33, %lsr.iv.next
  br i1 %exitcond.not.3, label %B150.endif.us.preheader, label %B88, !llvm.loop !82

B13409956:                                        ; preds = %B150.endif.us.preheader, %B0.endif
  store ptr null, ptr %retptr, align 8
  ret i32 0

B150.endif.us.preheader:                          ; preds = %B88, %B88.prol.loopexit, %middle.block
  %.idx393 = mul i64 %arg.F.5.1, 24
  %56 = getelementptr i8, ptr %arg.F.4, i64 %.idx393
  %57 = shl nuw i64 %arg.y.2, 3
  tail call void @llvm.memset.p0.i64(ptr align 8 %56, i8 0, i64 %57, i1 false)
  %.idx394 = shl i64 %arg.F.5.1, 5
  %58 = getelementptr i8, ptr %arg.F.4, i64 %.idx394
  tail call void @llvm.memset.p0.i64(ptr align 8 %58, i8 0, i64 %57, i1 false)
  %.idx395 = mul i64 %arg.F.5.1, 40
  %59 = getelementptr i8, ptr %arg.F.4, i64 %.idx395
  tail call void @llvm.memset.p0.i64(ptr align 8 %59, i8 0, i64 %57, i1 false)
  %.idx396 = mul i64 %arg.F.5.1, 48
  %60 = getelementptr i8, ptr %arg.F.4, i64 %.idx396
  tail call void @llvm.memset.p0.i64(ptr align 8 %60, i8 0, i64 %57, i1 false)
  br label %B13409956
}

; Function Attrs: noinline
define linkonce_odr void @NRT_decref(ptr %.1) local_unnamed_addr #3 {
.3:
  %.4 = icmp eq ptr %.1, null
  br i1 %.4, label %common.ret, label %.3.endif, !prof !0

common.ret:                                       ; preds = %.3, %.3.endif
  ret void

.3.endif:                                         ; preds = %.3
  fence release
  %0 = tail call i8 @llvm.x86.atomic.sub.cc.i64(ptr nonnull %.1, i64 1, i32 4)
  %1 = trunc i8 %0 to i1
  br i1 %1, label %.3.endif.if, label %common.ret, !prof !0

.3.endif.if:                                      ; preds = %.3.endif
  fence acquire
  tail call void @NRT_MemInfo_call_dtor(ptr nonnull %.1)
  ret void
}

; Function Attrs: nounwind
declare i8 @llvm.x86.atomic.sub.cc.i64(ptr, i64, i32 immarg) #4

declare void @NRT_MemInfo_call_dtor(ptr) local_unnamed_addr

define linkonce_odr range(i32 -1, -2) i32 @_ZN6charts7solvers2rk12initial_stepB3v84B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdddd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.f.0, ptr %arg.f.1, ptr readonly captures(address_is_null) %arg.f.2, ptr %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.f0.0, ptr readnone captures(none) %arg.f0.1, i64 %arg.f0.2, i64 %arg.f0.3, ptr readonly captures(none) %arg.f0.4, i64 %arg.f0.5.0, i64 %arg.f0.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, double %arg.interval, double %arg.hmax, double %arg.rtol, double %arg.atol, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.f1.0, ptr %arg.f1.1, i64 %arg.f1.2, i64 %arg.f1.3, ptr %arg.f1.4, i64 %arg.f1.5.0, i64 %arg.f1.6.0) local_unnamed_addr {
B0.endif:
  %.743 = alloca i32, align 4
  store i32 0, ptr %.743, align 4
  %.778 = alloca double, align 8
  store double 0.000000e+00, ptr %.778, align 8
  %excinfo.4 = alloca ptr, align 8
  store ptr null, ptr %excinfo.4, align 8
  tail call void @NRT_incref(ptr %arg.y.0)
  tail call void @NRT_incref(ptr %arg.f0.0)
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.ytmp.0)
  tail call void @NRT_incref(ptr %arg.f1.0)
  %.145 = icmp sgt i64 %arg.y.2, 0
  br i1 %.145, label %B58.preheader, label %B184

B58.preheader:                                    ; preds = %B0.endif
  br label %B58

B58:                                              ; preds = %B58.preheader, %B58.endif
  %d1.3.0345 = phi double [ %.391, %B58.endif ], [ 0.000000e+00, %B58.preheader ]
  %d0.3.0344 = phi double [ %.325, %B58.endif ], [ 0.000000e+00, %B58.preheader ]
  %.195338342 = phi i64 [ %.202, %B58.endif ], [ 0, %B58.preheader ]
  %0 = shl i64 %.195338342, 3
  %scevgep136 = getelementptr i8, ptr %arg.y.4, i64 %0
  %.256 = load double, ptr %scevgep136, align 8
  %.257 = tail call double @llvm.fabs.f64(double %.256)
  %.259 = fmul double %arg.rtol, %.257
  %.261 = fadd double %arg.atol, %.259
  %.292 = fcmp oeq double %.261, 0.000000e+00
  br i1 %.292, label %B58.if, label %B58.endif, !prof !0

B184:                                             ; preds = %B0.endif
  %.402 = icmp eq i64 %arg.y.2, 0
  br i1 %.402, label %B184.if, label %B322.endif.endif, !prof !83

B388:                                             ; preds = %B388.preheader5, %B388
  %.585350352 = phi i64 [ %.592.7, %B388 ], [ %.585350352.unr, %B388.preheader5 ]
  %sunkaddr83 = mul i64 %.585350352, 8
  %sunkaddr84 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr83
  %.646 = load double, ptr %sunkaddr84, align 8
  %sunkaddr85 = mul i64 %.585350352, 8
  %sunkaddr86 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr85
  %.676 = load double, ptr %sunkaddr86, align 8
  %.678 = fmul double %.19.i, %.676
  %.679 = fadd double %.646, %.678
  %sunkaddr = mul i64 %.585350352, 8
  %sunkaddr87 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr
  store double %.679, ptr %sunkaddr87, align 8
  %sunkaddr88 = mul i64 %.585350352, 8
  %sunkaddr89 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr88
  %sunkaddr90 = getelementptr i8, ptr %sunkaddr89, i64 8
  %.646.1 = load double, ptr %sunkaddr90, align 8
  %sunkaddr91 = mul i64 %.585350352, 8
  %sunkaddr92 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr91
  %sunkaddr93 = getelementptr i8, ptr %sunkaddr92, i64 8
  %.676.1 = load double, ptr %sunkaddr93, align 8
  %.678.1 = fmul double %.19.i, %.676.1
  %.679.1 = fadd double %.646.1, %.678.1
  %sunkaddr94 = mul i64 %.585350352, 8
  %sunkaddr95 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr94
  %sunkaddr96 = getelementptr i8, ptr %sunkaddr95, i64 8
  store double %.679.1, ptr %sunkaddr96, align 8
  %sunkaddr97 = mul i64 %.585350352, 8
  %sunkaddr98 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr97
  %sunkaddr99 = getelementptr i8, ptr %sunkaddr98, i64 16
  %.646.2 = load double, ptr %sunkaddr99, align 8
  %sunkaddr100 = mul i64 %.585350352, 8
  %sunkaddr101 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr100
  %sunkaddr102 = getelementptr i8, ptr %sunkaddr101, i64 16
  %.676.2 = load double, ptr %sunkaddr102, align 8
  %.678.2 = fmul double %.19.i, %.676.2
  %.679.2 = fadd double %.646.2, %.678.2
  %sunkaddr103 = mul i64 %.585350352, 8
  %sunkaddr104 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr103
  %sunkaddr105 = getelementptr i8, ptr %sunkaddr104, i64 16
  store double %.679.2, ptr %sunkaddr105, align 8
  %sunkaddr106 = mul i64 %.585350352, 8
  %sunkaddr107 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr106
  %sunkaddr108 = getelementptr i8, ptr %sunkaddr107, i64 24
  %.646.3 = load double, ptr %sunkaddr108, align 8
  %sunkaddr109 = mul i64 %.585350352, 8
  %sunkaddr110 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr109
  %sunkaddr111 = getelementptr i8, ptr %sunkaddr110, i64 24
  %.676.3 = load double, ptr %sunkaddr111, align 8
  %.678.3 = fmul double %.19.i, %.676.3
  %.679.3 = fadd double %.646.3, %.678.3
  %sunkaddr112 = mul i64 %.585350352, 8
  %sunkaddr113 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr112
  %sunkaddr114 = getelementptr i8, ptr %sunkaddr113, i64 24
  store double %.679.3, ptr %sunkaddr114, align 8
  %sunkaddr115 = mul i64 %.585350352, 8
  %sunkaddr116 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr115
  %sunkaddr117 = getelementptr i8, ptr %sunkaddr116, i64 32
  %.646.4 = load double, ptr %sunkaddr117, align 8
  %sunkaddr118 = mul i64 %.585350352, 8
  %sunkaddr119 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr118
  %sunkaddr120 = getelementptr i8, ptr %sunkaddr119, i64 32
  %.676.4 = load double, ptr %sunkaddr120, align 8
  %.678.4 = fmul double %.19.i, %.676.4
  %.679.4 = fadd double %.646.4, %.678.4
  %sunkaddr121 = mul i64 %.585350352, 8
  %sunkaddr122 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr121
  %sunkaddr123 = getelementptr i8, ptr %sunkaddr122, i64 32
  store double %.679.4, ptr %sunkaddr123, align 8
  %sunkaddr124 = mul i64 %.585350352, 8
  %sunkaddr125 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr124
  %sunkaddr126 = getelementptr i8, ptr %sunkaddr125, i64 40
  %.646.5 = load double, ptr %sunkaddr126, align 8
  %sunkaddr127 = mul i64 %.585350352, 8
  %sunkaddr128 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr127
  %sunkaddr129 = getelementptr i8, ptr %sunkaddr128, i64 40
  %.676.5 = load double, ptr %sunkaddr129, align 8
  %.678.5 = fmul double %.19.i, %.676.5
  %.679.5 = fadd double %.646.5, %.678.5
  %sunkaddr130 = mul i64 %.585350352, 8
  %sunkaddr131 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr130
  %sunkaddr132 = getelementptr i8, ptr %sunkaddr131, i64 40
  store double %.679.5, ptr %sunkaddr132, align 8
  %sunkaddr133 = mul i64 %.585350352, 8
  %sunkaddr134 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr133
  %sunkaddr135 = getelementptr i8, ptr %sunkaddr134, i64 48
  %.646.6 = load double, ptr %sunkaddr135, align 8
  %sunkaddr136 = mul i64 %.585350352, 8
  %sunkaddr137 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr136
  %sunkaddr138 = getelementptr i8, ptr %sunkaddr137, i64 48
  %.676.6 = load double, ptr %sunkaddr138, align 8
  %.678.6 = fmul double %.19.i, %.676.6
  %.679.6 = fadd double %.646.6, %.678.6
  %sunkaddr139 = mul i64 %.585350352, 8
  %sunkaddr140 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr139
  %sunkaddr141 = getelementptr i8, ptr %sunkaddr140, i64 48
  store double %.679.6, ptr %sunkaddr141, align 8
  %.592.7 = add nuw nsw i64 %.585350352, 8
  %sunkaddr142 = mul i64 %.585350352, 8
  %sunkaddr143 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr142
  %sunkaddr144 = getelementptr i8, ptr %sunkaddr143, i64 56
  %.646.7 = load double, ptr %sunkaddr144, align 8
  %sunkaddr145 = mul i64 %.585350352, 8
  %sunkaddr146 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr145
  %sunkaddr147 = getelementptr i8, ptr %sunkaddr146, i64 56
  %.676.7 = load double, ptr %sunkaddr147, align 8
  %.678.7 = fmul double %.19.i, %.676.7
  %.679.7 = fadd double %.646.7, %.678.7
  %sunkaddr148 = mul i64 %.585350352, 8
  %sunkaddr149 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr148
  %sunkaddr150 = getelementptr i8, ptr %sunkaddr149, i64 56
  store double %.679.7, ptr %sunkaddr150, align 8
  %exitcond371.not.7 = icmp eq i64 %arg.y.2, %.592.7
  br i1 %exitcond371.not.7, label %B438, label %B388, !llvm.loop !84

B438:                                             ; preds = %B388, %B388.prol.loopexit, %vec.epilog.middle.block, %middle.block, %B322.endif.endif
  %.715.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ytmp.0, 0
  %.715.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.0.insert, ptr %arg.ytmp.1, 1
  %.715.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.1.insert, i64 %arg.ytmp.2, 2
  %.715.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.2.insert, i64 %arg.ytmp.3, 3
  %.715.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.3.insert, ptr %arg.ytmp.4, 4
  %.715.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.4.insert, i64 %arg.ytmp.5.0, 5, 0
  %.715.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.5.0.insert, i64 %arg.ytmp.6.0, 6, 0
  %.716.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.par.0, 0
  %.716.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.0.insert, ptr %arg.par.1, 1
  %.716.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.1.insert, i64 %arg.par.2, 2
  %.716.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.2.insert, i64 %arg.par.3, 3
  %.716.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.3.insert, ptr %arg.par.4, 4
  %.716.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.4.insert, i64 %arg.par.5.0, 5, 0
  %.716.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.5.0.insert, i64 %arg.par.6.0, 6, 0
  %.717.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.f1.0, 0
  %.717.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.0.insert, ptr %arg.f1.1, 1
  %.717.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.1.insert, i64 %arg.f1.2, 2
  %.717.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.2.insert, i64 %arg.f1.3, 3
  %.717.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.3.insert, ptr %arg.f1.4, 4
  %.717.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.4.insert, i64 %arg.f1.5.0, 5, 0
  %.717.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.5.0.insert, i64 %arg.f1.6.0, 6, 0
  %.727 = icmp eq ptr %arg.f.2, null
  br i1 %.727, label %B438.if, label %B438.else, !prof !0

B500:                                             ; preds = %B500.preheader, %B500.endif
  %d2.3.0363 = phi double [ %.1073, %B500.endif ], [ 0.000000e+00, %B500.preheader ]
  %.912358361 = phi i64 [ %.919, %B500.endif ], [ 0, %B500.preheader ]
  %1 = shl i64 %.912358361, 3
  %scevgep56 = getelementptr i8, ptr %arg.y.4, i64 %1
  %.973 = load double, ptr %scevgep56, align 8
  %.974 = call double @llvm.fabs.f64(double %.973)
  %.976 = fmul double %arg.rtol, %.974
  %.978 = fadd double %arg.atol, %.976
  %.1040 = fcmp oeq double %.978, 0.000000e+00
  br i1 %.1040, label %B500.if, label %B500.endif, !prof !0

B686:                                             ; preds = %B610.endif.endif
  %.1139 = fmul double %.19.i, 1.000000e-03
  %.12.i = fcmp ogt double %.1139, 0x3EB0C6F7A0B5ED8D
  %.13.i = select i1 %.12.i, double %.1139, double 0x3EB0C6F7A0B5ED8D
  br label %B770.endif

common.ret:                                       ; preds = %B770.endif, %B726.endif.if, %B610.endif.if, %B500.if, %B438.else.if.if, %B438.if.if.endif.if, %B438.if.if.if, %B184.if, %B58.if
  %common.ret.op = phi i32 [ 1, %B58.if ], [ 0, %B770.endif ], [ 1, %B726.endif.if ], [ 1, %B184.if ], [ 1, %B500.if ], [ 1, %B610.endif.if ], [ 1, %B438.if.if.if ], [ 1, %B438.if.if.endif.if ], [ %.788, %B438.else.if.if ]
  ret i32 %common.ret.op

B58.if:                                           ; preds = %B58
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B58.endif:                                        ; preds = %B58
  %.202 = add nuw nsw i64 %.195338342, 1
  %.299 = fdiv double %.256, %.261
  %2 = shl i64 %.195338342, 3
  %scevgep82 = getelementptr i8, ptr %arg.f0.4, i64 %2
  %.357 = load double, ptr %scevgep82, align 8
  %.365 = fdiv double %.357, %.261
  %.147.i18 = fmul double %.365, %.365
  %.147.i = fmul double %.299, %.299
  %.325 = fadd double %d0.3.0344, %.147.i
  %.391 = fadd double %d1.3.0345, %.147.i18
  %exitcond.not = icmp eq i64 %arg.y.2, %.202
  br i1 %exitcond.not, label %B322.endif.endif, label %B58

B184.if:                                          ; preds = %B184
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B322.endif.endif:                                 ; preds = %B58.endif, %B184
  %d1.3.0.lcssa378 = phi double [ 0.000000e+00, %B184 ], [ %.391, %B58.endif ]
  %d0.3.0.lcssa377 = phi double [ 0.000000e+00, %B184 ], [ %.325, %B58.endif ]
  %.401379 = sitofp i64 %arg.y.2 to double
  %.409 = fdiv double %d0.3.0.lcssa377, %.401379
  %.412 = tail call double @sqrt(double %.409)
  %.426 = fdiv double %d1.3.0.lcssa378, %.401379
  %.429 = tail call double @sqrt(double %.426)
  %.434 = fcmp olt double %.412, 1.000000e-05
  %.437 = fcmp olt double %.429, 1.000000e-05
  %or.cond = select i1 %.434, i1 true, i1 %.437
  %.446 = fmul double %.412, 1.000000e-02
  %.457 = fdiv double %.446, %.429
  %h0.3.0 = select i1 %or.cond, double 0x3EB0C6F7A0B5ED8D, double %.457
  %.16.i = fcmp olt double %arg.interval, %h0.3.0
  %.17.i = select i1 %.16.i, double %arg.interval, double %h0.3.0
  %.18.i = fcmp olt double %arg.hmax, %.17.i
  %.19.i = select i1 %.18.i, double %arg.hmax, double %.17.i
  %.579351.not = icmp slt i64 %arg.y.2, 1
  br i1 %.579351.not, label %B438, label %iter.check

iter.check:                                       ; preds = %B322.endif.endif
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check, label %B388.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %iter.check
  %3 = ptrtoint ptr %arg.ytmp.4 to i64
  %4 = ptrtoint ptr %arg.y.4 to i64
  %5 = ptrtoint ptr %arg.f0.4 to i64
  %6 = sub i64 %3, %4
  %diff.check = icmp ult i64 %6, 256
  %7 = sub i64 %3, %5
  %diff.check36 = icmp ult i64 %7, 256
  %conflict.rdx = or i1 %diff.check, %diff.check36
  br i1 %conflict.rdx, label %B388.preheader, label %vector.main.loop.iter.check

vector.main.loop.iter.check:                      ; preds = %vector.memcheck
  %const = bitcast i64 9223372036854775776 to i64
  %min.iters.check37 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check37, label %vec.epilog.ph, label %vector.ph

vector.ph:                                        ; preds = %vector.main.loop.iter.check
  %n.vec = and i64 %arg.y.2, %const
  %broadcast.splatinsert = insertelement <8 x double> poison, double %.19.i, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %sunkaddr151 = mul i64 %index, 8
  %sunkaddr152 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr151
  %wide.load = load <8 x double>, ptr %sunkaddr152, align 8
  %sunkaddr153 = mul i64 %index, 8
  %sunkaddr154 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr153
  %sunkaddr155 = getelementptr i8, ptr %sunkaddr154, i64 64
  %wide.load38 = load <8 x double>, ptr %sunkaddr155, align 8
  %sunkaddr156 = mul i64 %index, 8
  %sunkaddr157 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr156
  %sunkaddr158 = getelementptr i8, ptr %sunkaddr157, i64 128
  %wide.load39 = load <8 x double>, ptr %sunkaddr158, align 8
  %sunkaddr159 = mul i64 %index, 8
  %sunkaddr160 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr159
  %sunkaddr161 = getelementptr i8, ptr %sunkaddr160, i64 192
  %wide.load40 = load <8 x double>, ptr %sunkaddr161, align 8
  %sunkaddr162 = mul i64 %index, 8
  %sunkaddr163 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr162
  %wide.load41 = load <8 x double>, ptr %sunkaddr163, align 8
  %sunkaddr164 = mul i64 %index, 8
  %sunkaddr165 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr164
  %sunkaddr166 = getelementptr i8, ptr %sunkaddr165, i64 64
  %wide.load42 = load <8 x double>, ptr %sunkaddr166, align 8
  %sunkaddr167 = mul i64 %index, 8
  %sunkaddr168 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr167
  %sunkaddr169 = getelementptr i8, ptr %sunkaddr168, i64 128
  %wide.load43 = load <8 x double>, ptr %sunkaddr169, align 8
  %sunkaddr170 = mul i64 %index, 8
  %sunkaddr171 = getelementptr i8, ptr %arg.f0.4, i64 %sunkaddr170
  %sunkaddr172 = getelementptr i8, ptr %sunkaddr171, i64 192
  %wide.load44 = load <8 x double>, ptr %sunkaddr172, align 8
  %8 = fmul <8 x double> %broadcast.splat, %wide.load41
  %9 = fmul <8 x double> %broadcast.splat, %wide.load42
  %10 = fmul <8 x double> %broadcast.splat, %wide.load43
  %11 = fmul <8 x double> %broadcast.splat, %wide.load44
  %12 = fadd <8 x double> %wide.load, %8
  %13 = fadd <8 x double> %wide.load38, %9
  %14 = fadd <8 x double> %wide.load39, %10
  %15 = fadd <8 x double> %wide.load40, %11
  %sunkaddr173 = mul i64 %index, 8
  %sunkaddr174 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr173
  store <8 x double> %12, ptr %sunkaddr174, align 8
  %sunkaddr175 = mul i64 %index, 8
  %sunkaddr176 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr175
  %sunkaddr177 = getelementptr i8, ptr %sunkaddr176, i64 64
  store <8 x double> %13, ptr %sunkaddr177, align 8
  %sunkaddr178 = mul i64 %index, 8
  %sunkaddr179 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr178
  %sunkaddr180 = getelementptr i8, ptr %sunkaddr179, i64 128
  store <8 x double> %14, ptr %sunkaddr180, align 8
  %sunkaddr181 = mul i64 %index, 8
  %sunkaddr182 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr181
  %sunkaddr183 = getelementptr i8, ptr %sunkaddr182, i64 192
  store <8 x double> %15, ptr %sunkaddr183, align 8
  %index.next = add nuw nsw i64 %index, 32
  %16 = icmp eq i64 %n.vec, %index.next
  br i1 %16, label %middle.block, label %vector.body, !llvm.loop !85

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B438, label %vec.epilog.iter.check

vec.epilog.iter.check:                            ; preds = %middle.block
  %17 = and i64 %arg.y.2, 28
  %min.epilog.iters.check = icmp eq i64 %17, 0
  br i1 %min.epilog.iters.check, label %B388.preheader, label %vec.epilog.ph, !prof !9

vec.epilog.ph:                                    ; preds = %vec.epilog.iter.check, %vector.main.loop.iter.check
  %vec.epilog.resume.val = phi i64 [ %n.vec, %vec.epilog.iter.check ], [ 0, %vector.main.loop.iter.check ]
  %const_mat = add i64 %const, 28
  %n.vec46 = and i64 %arg.y.2, %const_mat
  %broadcast.splatinsert47 = insertelement <4 x double> poison, double %.19.i, i64 0
  %broadcast.splat48 = shufflevector <4 x double> %broadcast.splatinsert47, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body

vec.epilog.vector.body:                           ; preds = %vec.epilog.vector.body, %vec.epilog.ph
  %index49 = phi i64 [ %vec.epilog.resume.val, %vec.epilog.ph ], [ %index.next52, %vec.epilog.vector.body ]
  %18 = shl i64 %index49, 3
  %scevgep110 = getelementptr i8, ptr %arg.y.4, i64 %18
  %wide.load50 = load <4 x double>, ptr %scevgep110, align 8
  %scevgep109 = getelementptr i8, ptr %arg.f0.4, i64 %18
  %wide.load51 = load <4 x double>, ptr %scevgep109, align 8
  %19 = fmul <4 x double> %broadcast.splat48, %wide.load51
  %20 = fadd <4 x double> %wide.load50, %19
  %21 = shl i64 %index49, 3
  %scevgep57 = getelementptr i8, ptr %arg.ytmp.4, i64 %21
  store <4 x double> %20, ptr %scevgep57, align 8
  %index.next52 = add nuw i64 %index49, 4
  %22 = icmp eq i64 %n.vec46, %index.next52
  br i1 %22, label %vec.epilog.middle.block, label %vec.epilog.vector.body, !llvm.loop !86

vec.epilog.middle.block:                          ; preds = %vec.epilog.vector.body
  %cmp.n53 = icmp eq i64 %arg.y.2, %n.vec46
  br i1 %cmp.n53, label %B438, label %B388.preheader

B388.preheader:                                   ; preds = %vec.epilog.middle.block, %vec.epilog.iter.check, %vector.memcheck, %iter.check
  %.585350352.ph = phi i64 [ 0, %iter.check ], [ 0, %vector.memcheck ], [ %n.vec, %vec.epilog.iter.check ], [ %n.vec46, %vec.epilog.middle.block ]
  %23 = sub nsw i64 %arg.y.2, %.585350352.ph
  %xtraiter = and i64 %23, 7
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B388.prol.loopexit, label %B388.prol.preheader

B388.prol.preheader:                              ; preds = %B388.preheader
  br label %B388.prol

B388.prol:                                        ; preds = %B388.prol.preheader, %B388.prol
  %lsr.iv = phi i64 [ %lsr.iv.next, %B388.prol ], [ %xtraiter, %B388.prol.preheader ]
  %.585350352.prol = phi i64 [ %.592.prol, %B388.prol ], [ %.585350352.ph, %B388.prol.preheader ]
  %.592.prol = add nuw i64 %.585350352.prol, 1
  %24 = shl i64 %.585350352.prol, 3
  %scevgep107 = getelementptr i8, ptr %arg.y.4, i64 %24
  %.646.prol = load double, ptr %scevgep107, align 8
  %scevgep106 = getelementptr i8, ptr %arg.f0.4, i64 %24
  %.676.prol = load double, ptr %scevgep106, align 8
  %.678.prol = fmul double %.19.i, %.676.prol
  %.679.prol = fadd double %.646.prol, %.678.prol
  %25 = shl i64 %.585350352.prol, 3
  %scevgep55 = getelementptr i8, ptr %arg.ytmp.4, i64 %25
  store double %.679.prol, ptr %scevgep55, align 8
  %lsr.iv.next = add nsw i64 %lsr.iv, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next, 0
  br i1 %prol.iter.cmp.not, label %B388.prol.loopexit, label %B388.prol, !llvm.loop !87

B388.prol.loopexit:                               ; preds = %B388.prol, %B388.preheader
  %.585350352.unr = phi i64 [ %.585350352.ph, %B388.preheader ], [ %.592.prol, %B388.prol ]
  %26 = sub nsw i64 %.585350352.ph, %arg.y.2
  %27 = icmp ugt i64 %26, -8
  br i1 %27, label %B438, label %B388.preheader5

B388.preheader5:                                  ; preds = %B388.prol.loopexit
  br label %B388

B438.if:                                          ; preds = %B438
  %.731 = icmp eq ptr %arg.f.0, null
  br i1 %.731, label %B438.if.if, label %B438.if.endif, !prof !0

B438.else:                                        ; preds = %B438
  store double 0.000000e+00, ptr %.778, align 8
  %.788 = call i32 %arg.f.2(ptr nonnull %.778, ptr nonnull %excinfo.4, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.f1.0, ptr %arg.f1.1, i64 %arg.f1.2, i64 %arg.f1.3, ptr %arg.f1.4, i64 %arg.f1.5.0, i64 %arg.f1.6.0)
  switch i32 %.788, label %B438.else.if.if [
    i32 -2, label %B438.endif.endif
    i32 0, label %B438.endif.endif
  ], !prof !4

B438.if.if:                                       ; preds = %B438.if
  %.733 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers2rk12initial_stepB3v84B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdddd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE, align 8
  %.734 = icmp eq ptr %.733, null
  br i1 %.734, label %B438.if.if.if, label %B438.if.if.endif, !prof !0

B438.if.endif:                                    ; preds = %B438.if.if.endif.endif, %B438.if
  %fptr_of_f.0 = phi ptr [ %.764, %B438.if.if.endif.endif ], [ %arg.f.0, %B438.if ]
  %.774 = call double %fptr_of_f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.715.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.716.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.717.fca.6.0.insert)
  br label %B438.endif.endif

B438.if.if.if:                                    ; preds = %B438.if.if
  store ptr @.const.picklebuf.c3243e19d8c377ae31c00ff41e00cb6ab90277f0, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B438.if.if.endif:                                 ; preds = %B438.if.if
  call void @numba_gil_ensure(ptr nonnull %.743)
  %.746 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.30)
  %.747 = call ptr @PyObject_GetAttrString(ptr %.746, ptr nonnull @.const._get_wrapper_address.31)
  call void @Py_DecRef(ptr %.746)
  %.755 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.32, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.33)
  %.756 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.747, ptr %arg.f.1, ptr %.755, ptr null)
  %.757 = icmp eq ptr %.756, null
  br i1 %.757, label %B438.if.if.endif.if, label %B438.if.if.endif.endif, !prof !0

B438.if.if.endif.if:                              ; preds = %B438.if.if.endif
  store ptr @.const.picklebuf.4e3d529372d5f63b747cb9250801d0e712742805, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B438.if.if.endif.endif:                           ; preds = %B438.if.if.endif
  %.764 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.756)
  call void @Py_DecRef(ptr nonnull %.756)
  call void @numba_gil_release(ptr nonnull %.743)
  br label %B438.if.endif

B438.else.if.if:                                  ; preds = %B438.else
  %.796 = icmp sgt i32 %.788, 0
  %.789 = load ptr, ptr %excinfo.4, align 8
  %.797 = select i1 %.796, ptr %.789, ptr undef
  store ptr %.797, ptr %excinfo, align 8
  br label %common.ret

B438.endif.endif:                                 ; preds = %B438.if.endif, %B438.else, %B438.else
  %28 = icmp slt i64 %arg.y.2, 1
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.par.0)
  br i1 %28, label %B610.endif, label %B500.preheader

B500.preheader:                                   ; preds = %B438.endif.endif
  br label %B500

B500.if:                                          ; preds = %B500
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B500.endif:                                       ; preds = %B500
  %.919 = add nuw nsw i64 %.912358361, 1
  %29 = shl i64 %.912358361, 3
  %scevgep7 = getelementptr i8, ptr %arg.f1.4, i64 %29
  %.1008 = load double, ptr %scevgep7, align 8
  %30 = shl i64 %.912358361, 3
  %scevgep6 = getelementptr i8, ptr %arg.f0.4, i64 %30
  %.1038 = load double, ptr %scevgep6, align 8
  %.1039 = fsub double %.1008, %.1038
  %.1047 = fdiv double %.1039, %.978
  %.147.i30 = fmul double %.1047, %.1047
  %.1073 = fadd double %d2.3.0363, %.147.i30
  %exitcond372.not = icmp eq i64 %arg.y.2, %.919
  br i1 %exitcond372.not, label %B610.endif, label %B500

B610.endif:                                       ; preds = %B500.endif, %B438.endif.endif
  %d2.3.0.lcssa = phi double [ 0.000000e+00, %B438.endif.endif ], [ %.1073, %B500.endif ]
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.f1.0)
  call void @NRT_decref(ptr %arg.f0.0)
  %.1117 = fcmp oeq double %.19.i, 0.000000e+00
  br i1 %.1117, label %B610.endif.if, label %B610.endif.endif, !prof !0

B610.endif.if:                                    ; preds = %B610.endif
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B610.endif.endif:                                 ; preds = %B610.endif
  %.1110 = fdiv double %d2.3.0.lcssa, %.401379
  %.1115 = call double @sqrt(double %.1110)
  %.1124 = fdiv double %.1115, %.19.i
  %.1129 = fcmp ole double %.429, 1.000000e-15
  %.1132 = fcmp ole double %.1124, 1.000000e-15
  %or.cond321 = select i1 %.1129, i1 %.1132, i1 false
  br i1 %or.cond321, label %B686, label %B726.endif

B726.endif:                                       ; preds = %B610.endif.endif
  %.12.i7 = fcmp ogt double %.1124, %.429
  %.13.i8 = select i1 %.12.i7, double %.1124, double %.429
  %.1206 = fcmp oeq double %.13.i8, 0.000000e+00
  br i1 %.1206, label %B726.endif.if, label %B726.endif.endif, !prof !0

B726.endif.if:                                    ; preds = %B726.endif
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.29, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B726.endif.endif:                                 ; preds = %B726.endif
  %.1213 = fdiv double 1.000000e-02, %.13.i8
  %.1214 = call double @llvm.pow.f64(double %.1213, double 1.250000e-01)
  br label %B770.endif

B770.endif:                                       ; preds = %B726.endif.endif, %B686
  %h1.2.0 = phi double [ %.1214, %B726.endif.endif ], [ %.13.i, %B686 ]
  %.1219 = fmul double %.19.i, 1.000000e+02
  %.20.i = fcmp olt double %h1.2.0, %.1219
  %.21.i = select i1 %.20.i, double %h1.2.0, double %.1219
  %.22.i = fcmp olt double %arg.interval, %.21.i
  %.23.i = select i1 %.22.i, double %arg.interval, double %.21.i
  %.24.i = fcmp olt double %arg.hmax, %.23.i
  %.25.i = select i1 %.24.i, double %arg.hmax, double %.23.i
  store double %.25.i, ptr %retptr, align 8
  br label %common.ret
}

; Function Attrs: mustprogress nofree noinline norecurse nounwind willreturn memory(argmem: readwrite)
define linkonce_odr void @NRT_incref(ptr captures(address_is_null) %.1) local_unnamed_addr #5 {
.3:
  %.4 = icmp eq ptr %.1, null
  br i1 %.4, label %common.ret, label %.3.endif, !prof !0

common.ret:                                       ; preds = %.3.endif, %.3
  ret void

.3.endif:                                         ; preds = %.3
  %.4.i = atomicrmw add ptr %.1, i64 1 monotonic, align 8
  br label %common.ret
}

; Function Attrs: mustprogress nocallback nocreateundeforpoison nofree nosync nounwind speculatable willreturn memory(none)
declare double @llvm.fabs.f64(double) #6

; Function Attrs: mustprogress nocallback nofree nosync nounwind willreturn memory(none)
declare double @sqrt(double) local_unnamed_addr #7

; Function Attrs: mustprogress nocallback nocreateundeforpoison nofree nosync nounwind speculatable willreturn memory(none)
declare double @llvm.pow.f64(double, double) #6

define linkonce_odr range(i32 -1, -2) i32 @_ZN6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.f.0, ptr %arg.f.1, ptr readonly captures(address_is_null) %arg.f.2, ptr %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %arg.rtol, double %arg.atol) local_unnamed_addr {
B0.endif.endif:
  %.233 = alloca double, align 8
  %excinfo.1 = alloca ptr, align 8
  store ptr null, ptr %excinfo.1, align 8
  %.845 = alloca i32, align 4
  store i32 0, ptr %.845, align 4
  %.880 = alloca double, align 8
  store double 0.000000e+00, ptr %.880, align 8
  %excinfo.3 = alloca ptr, align 8
  store ptr null, ptr %excinfo.3, align 8
  tail call void @NRT_incref(ptr %arg.y.0)
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.K.0)
  tail call void @NRT_incref(ptr %arg.ytmp.0)
  tail call void @NRT_incref(ptr %arg.ynew.0)
  br label %B66

B66:                                              ; preds = %B66.endif.endif, %B0.endif.endif
  %hmin.3.0512 = phi double [ 1.000000e+300, %B0.endif.endif ], [ %.13.i, %B66.endif.endif ]
  %.194506510 = phi i64 [ 1, %B0.endif.endif ], [ %.201, %B66.endif.endif ]
  store double 0.000000e+00, ptr %.233, align 8
  %.247 = call i32 @_ZN6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.233, ptr nonnull %excinfo.1, ptr %arg.f.0, ptr %arg.f.1, ptr %arg.f.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, i64 %.194506510, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0)
  %cond = icmp eq i32 %.247, 0
  br i1 %cond, label %B66.endif.endif, label %B66.if.if, !prof !1

B314:                                             ; preds = %B172.endif.endif, %B172.endif.endif.prol.loopexit, %middle.block, %B140.endif
  %.786.idx = mul i64 %arg.K.5.1, 96
  %.786 = getelementptr i8, ptr %arg.K.4, i64 %.786.idx
  %.814.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.K.0, 0
  %.814.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.0.insert, ptr %arg.K.1, 1
  %.814.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.1.insert, i64 %arg.K.5.1, 2
  %.814.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.2.insert, i64 %arg.K.3, 3
  %.814.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.3.insert, ptr %.786, 4
  %.814.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.4.insert, i64 %arg.K.5.1, 5, 0
  %.814.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.5.0.insert, i64 %arg.K.6.1, 6, 0
  tail call void @NRT_incref(ptr %arg.K.0)
  %.818.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ynew.0, 0
  %.818.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.0.insert, ptr %arg.ynew.1, 1
  %.818.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.1.insert, i64 %arg.ynew.2, 2
  %.818.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.2.insert, i64 %arg.ynew.3, 3
  %.818.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.3.insert, ptr %arg.ynew.4, 4
  %.818.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.4.insert, i64 %arg.ynew.5.0, 5, 0
  %.818.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.5.0.insert, i64 %arg.ynew.6.0, 6, 0
  %.819.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.par.0, 0
  %.819.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.0.insert, ptr %arg.par.1, 1
  %.819.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.1.insert, i64 %arg.par.2, 2
  %.819.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.2.insert, i64 %arg.par.3, 3
  %.819.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.3.insert, ptr %arg.par.4, 4
  %.819.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.4.insert, i64 %arg.par.5.0, 5, 0
  %.819.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.5.0.insert, i64 %arg.par.6.0, 6, 0
  %.829 = icmp eq ptr %arg.f.2, null
  br i1 %.829, label %B314.if, label %B314.else, !prof !0

B766:                                             ; preds = %B600.endif.endif, %B314.endif.endif.endif
  %e5.2.0.lcssa = phi double [ 0.000000e+00, %B314.endif.endif.endif ], [ %.1583, %B600.endif.endif ]
  %e3.2.0.lcssa = phi double [ 0.000000e+00, %B314.endif.endif.endif ], [ %.1622, %B600.endif.endif ]
  call void @NRT_decref(ptr %arg.ynew.0)
  call void @NRT_decref(ptr %arg.y.0)
  call void @NRT_decref(ptr %arg.K.0)
  %.1652 = fcmp oeq double %e5.2.0.lcssa, 0.000000e+00
  %.1655 = fcmp oeq double %e3.2.0.lcssa, 0.000000e+00
  %or.cond = select i1 %.1652, i1 %.1655, i1 false
  br i1 %or.cond, label %B790, label %B798

common.ret:                                       ; preds = %B798.endif, %B798.if, %B600.endif.if, %B314.else.if.if, %B314.if.if.endif.if, %B314.if.if.if, %B66.if.if, %B790
  %common.ret.op = phi i32 [ 0, %B790 ], [ %.247, %B66.if.if ], [ 0, %B798.endif ], [ 1, %B314.if.if.if ], [ 1, %B314.if.if.endif.if ], [ %.890, %B314.else.if.if ], [ 1, %B798.if ], [ 1, %B600.endif.if ]
  ret i32 %common.ret.op

B790:                                             ; preds = %B766
  store double 0.000000e+00, ptr %retptr, align 8
  %retptr.repack488 = getelementptr inbounds nuw i8, ptr %retptr, i64 8
  store double %.13.i13, ptr %retptr.repack488, align 8
  br label %common.ret

B798:                                             ; preds = %B766
  %.1685 = fmul double %e3.2.0.lcssa, 1.000000e-02
  %.1689 = fadd double %e5.2.0.lcssa, %.1685
  %.1693 = sitofp i64 %arg.y.2 to double
  %.1694 = fmul double %.1689, %.1693
  %.1697 = call double @sqrt(double %.1694)
  %.1698 = fcmp oeq double %.1697, 0.000000e+00
  br i1 %.1698, label %B798.if, label %B798.endif, !prof !0

B66.if.if:                                        ; preds = %B66
  %.255 = icmp sgt i32 %.247, 0
  %.248 = load ptr, ptr %excinfo.1, align 8
  %.256 = select i1 %.255, ptr %.248, ptr undef
  store ptr %.256, ptr %excinfo, align 8
  br label %common.ret

B66.endif.endif:                                  ; preds = %B66
  %.201 = add nuw nsw i64 %.194506510, 1
  %.257 = load double, ptr %.233, align 8
  %.12.i = fcmp olt double %.257, %hmin.3.0512
  %.13.i = select i1 %.12.i, double %.257, double %hmin.3.0512
  %exitcond.not = icmp eq i64 %.201, 12
  br i1 %exitcond.not, label %B140.endif, label %B66

B140.endif:                                       ; preds = %B66.endif.endif
  tail call void @NRT_decref(ptr %arg.ytmp.0)
  %.346 = icmp sgt i64 %arg.y.2, 0
  br i1 %.346, label %B172.endif.endif.preheader, label %B314

B172.endif.endif.preheader:                       ; preds = %B140.endif
  %gep519.2.idx = shl i64 %arg.K.5.1, 4
  %gep519.3.idx = mul i64 %arg.K.5.1, 24
  %gep519.4.idx = shl i64 %arg.K.5.1, 5
  %gep519.5.idx = mul i64 %arg.K.5.1, 40
  %gep519.6.idx = mul i64 %arg.K.5.1, 48
  %gep519.7.idx = mul i64 %arg.K.5.1, 56
  %gep519.8.idx = shl i64 %arg.K.5.1, 6
  %gep519.9.idx = mul i64 %arg.K.5.1, 72
  %gep519.10.idx = mul i64 %arg.K.5.1, 80
  %gep519.11.idx = mul i64 %arg.K.5.1, 88
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 16
  br i1 %min.iters.check, label %B172.endif.endif.preheader70, label %vector.memcheck

vector.memcheck:                                  ; preds = %B172.endif.endif.preheader
  %0 = ptrtoint ptr %arg.ynew.4 to i64
  %1 = ptrtoint ptr %arg.K.4 to i64
  %2 = ptrtoint ptr %arg.y.4 to i64
  %3 = sub i64 %0, %1
  %4 = sub i64 %3, %gep519.11.idx
  %diff.check = icmp ult i64 %4, 64
  %5 = sub i64 %3, %gep519.10.idx
  %diff.check34 = icmp ult i64 %5, 64
  %conflict.rdx = or i1 %diff.check, %diff.check34
  %6 = sub i64 %3, %gep519.9.idx
  %diff.check35 = icmp ult i64 %6, 64
  %conflict.rdx36 = or i1 %diff.check35, %conflict.rdx
  %7 = sub i64 %3, %gep519.8.idx
  %diff.check37 = icmp ult i64 %7, 64
  %conflict.rdx38 = or i1 %diff.check37, %conflict.rdx36
  %8 = sub i64 %3, %gep519.7.idx
  %diff.check39 = icmp ult i64 %8, 64
  %conflict.rdx40 = or i1 %diff.check39, %conflict.rdx38
  %9 = sub i64 %3, %gep519.6.idx
  %diff.check41 = icmp ult i64 %9, 64
  %conflict.rdx42 = or i1 %diff.check41, %conflict.rdx40
  %10 = sub i64 %3, %gep519.5.idx
  %diff.check43 = icmp ult i64 %10, 64
  %conflict.rdx44 = or i1 %diff.check43, %conflict.rdx42
  %11 = sub i64 %3, %gep519.4.idx
  %diff.check45 = icmp ult i64 %11, 64
  %conflict.rdx46 = or i1 %diff.check45, %conflict.rdx44
  %12 = sub i64 %3, %gep519.3.idx
  %diff.check47 = icmp ult i64 %12, 64
  %conflict.rdx48 = or i1 %diff.check47, %conflict.rdx46
  %13 = sub i64 %3, %gep519.2.idx
  %diff.check49 = icmp ult i64 %13, 64
  %conflict.rdx50 = or i1 %diff.check49, %conflict.rdx48
  %14 = shl i64 %arg.K.5.1, 3
  %15 = sub i64 %3, %14
  %diff.check51 = icmp ult i64 %15, 64
  %conflict.rdx52 = or i1 %diff.check51, %conflict.rdx50
  %diff.check53 = icmp ult i64 %3, 64
  %conflict.rdx54 = or i1 %diff.check53, %conflict.rdx52
  %16 = sub i64 %0, %2
  %diff.check56 = icmp ult i64 %16, 64
  %conflict.rdx57 = or i1 %diff.check56, %conflict.rdx54
  br i1 %conflict.rdx57, label %B172.endif.endif.preheader70, label %vector.ph

vector.ph:                                        ; preds = %vector.memcheck
  %n.vec = and i64 %arg.y.2, 9223372036854775800
  %broadcast.splatinsert = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %17 = shl i64 %index, 3
  %scevgep127 = getelementptr i8, ptr %arg.K.4, i64 %17
  %wide.load = load <8 x double>, ptr %scevgep127, align 8
  %18 = fmul <8 x double> %wide.load, splat (double 0x3FABCC6368D1177C)
  %19 = fadd <8 x double> %18, zeroinitializer
  %scevgep128 = getelementptr i8, ptr %scevgep127, i64 %14
  %wide.load58 = load <8 x double>, ptr %scevgep128, align 8
  %20 = fmul <8 x double> %wide.load58, zeroinitializer
  %21 = fadd <8 x double> %19, %20
  %scevgep129 = getelementptr i8, ptr %scevgep128, i64 %14
  %wide.load59 = load <8 x double>, ptr %scevgep129, align 8
  %22 = fmul <8 x double> %wide.load59, zeroinitializer
  %23 = fadd <8 x double> %21, %22
  %scevgep130 = getelementptr i8, ptr %scevgep129, i64 %14
  %wide.load60 = load <8 x double>, ptr %scevgep130, align 8
  %24 = fmul <8 x double> %wide.load60, zeroinitializer
  %25 = fadd <8 x double> %23, %24
  %scevgep131 = getelementptr i8, ptr %scevgep130, i64 %14
  %wide.load61 = load <8 x double>, ptr %scevgep131, align 8
  %26 = fmul <8 x double> %wide.load61, zeroinitializer
  %27 = fadd <8 x double> %25, %26
  %scevgep132 = getelementptr i8, ptr %scevgep131, i64 %14
  %wide.load62 = load <8 x double>, ptr %scevgep132, align 8
  %28 = fmul <8 x double> %wide.load62, splat (double 0x4011CD1ED2AD5AE2)
  %29 = fadd <8 x double> %27, %28
  %scevgep133 = getelementptr i8, ptr %scevgep132, i64 %14
  %wide.load63 = load <8 x double>, ptr %scevgep133, align 8
  %30 = fmul <8 x double> %wide.load63, splat (double 0x3FFE43A845D5AB9F)
  %31 = fadd <8 x double> %29, %30
  %scevgep134 = getelementptr i8, ptr %scevgep133, i64 %14
  %wide.load64 = load <8 x double>, ptr %scevgep134, align 8
  %32 = fmul <8 x double> %wide.load64, splat (double 0x4017346ECF96AF43)
  %33 = fsub <8 x double> %31, %32
  %scevgep135 = getelementptr i8, ptr %scevgep134, i64 %14
  %wide.load65 = load <8 x double>, ptr %scevgep135, align 8
  %34 = fmul <8 x double> %wide.load65, splat (double 0x3FD3EA1DF2F0EB98)
  %35 = fadd <8 x double> %33, %34
  %scevgep136 = getelementptr i8, ptr %scevgep135, i64 %14
  %wide.load66 = load <8 x double>, ptr %scevgep136, align 8
  %36 = fmul <8 x double> %wide.load66, splat (double 0x3FC37A028F43B002)
  %37 = fsub <8 x double> %35, %36
  %scevgep137 = getelementptr i8, ptr %scevgep136, i64 %14
  %wide.load67 = load <8 x double>, ptr %scevgep137, align 8
  %38 = fmul <8 x double> %wide.load67, splat (double 0x3FC9C657697FE72D)
  %39 = fadd <8 x double> %37, %38
  %scevgep138 = getelementptr i8, ptr %scevgep137, i64 %14
  %wide.load68 = load <8 x double>, ptr %scevgep138, align 8
  %40 = fmul <8 x double> %wide.load68, splat (double 0x3FA6E44F50AB6BC2)
  %41 = fadd <8 x double> %39, %40
  %42 = shl i64 %index, 3
  %scevgep29 = getelementptr i8, ptr %arg.y.4, i64 %42
  %wide.load69 = load <8 x double>, ptr %scevgep29, align 8
  %43 = fmul <8 x double> %broadcast.splat, %41
  %44 = fadd <8 x double> %wide.load69, %43
  %45 = shl i64 %index, 3
  %scevgep28 = getelementptr i8, ptr %arg.ynew.4, i64 %45
  store <8 x double> %44, ptr %scevgep28, align 8
  %index.next = add nuw nsw i64 %index, 8
  %46 = icmp eq i64 %n.vec, %index.next
  br i1 %46, label %middle.block, label %vector.body, !llvm.loop !88

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B314, label %B172.endif.endif.preheader70

B172.endif.endif.preheader70:                     ; preds = %middle.block, %vector.memcheck, %B172.endif.endif.preheader
  %.394521526.ph = phi i64 [ 0, %vector.memcheck ], [ 0, %B172.endif.endif.preheader ], [ %n.vec, %middle.block ]
  %.neg = or disjoint i64 %.394521526.ph, 1
  %xtraiter = and i64 %arg.y.2, 1
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B172.endif.endif.prol.loopexit, label %B172.endif.endif.prol

B172.endif.endif.prol:                            ; preds = %B172.endif.endif.preheader70
  %invariant.gep.prol = getelementptr double, ptr %arg.K.4, i64 %.394521526.ph
  %.659.prol = load double, ptr %invariant.gep.prol, align 8
  %.662.prol = fmul double %.659.prol, 0x3FABCC6368D1177C
  %.664.prol = fadd double %.662.prol, 0.000000e+00
  %gep519.1.prol = getelementptr double, ptr %invariant.gep.prol, i64 %arg.K.5.1
  %.659.1.prol = load double, ptr %gep519.1.prol, align 8
  %.662.1.prol = fmul double %.659.1.prol, 0.000000e+00
  %.664.1.prol = fadd double %.664.prol, %.662.1.prol
  %gep519.2.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.2.idx
  %.659.2.prol = load double, ptr %gep519.2.prol, align 8
  %.662.2.prol = fmul double %.659.2.prol, 0.000000e+00
  %.664.2.prol = fadd double %.664.1.prol, %.662.2.prol
  %gep519.3.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.3.idx
  %.659.3.prol = load double, ptr %gep519.3.prol, align 8
  %.662.3.prol = fmul double %.659.3.prol, 0.000000e+00
  %.664.3.prol = fadd double %.664.2.prol, %.662.3.prol
  %gep519.4.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.4.idx
  %.659.4.prol = load double, ptr %gep519.4.prol, align 8
  %.662.4.prol = fmul double %.659.4.prol, 0.000000e+00
  %.664.4.prol = fadd double %.664.3.prol, %.662.4.prol
  %gep519.5.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.5.idx
  %.659.5.prol = load double, ptr %gep519.5.prol, align 8
  %.662.5.prol = fmul double %.659.5.prol, 0x4011CD1ED2AD5AE2
  %.664.5.prol = fadd double %.664.4.prol, %.662.5.prol
  %gep519.6.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.6.idx
  %.659.6.prol = load double, ptr %gep519.6.prol, align 8
  %.662.6.prol = fmul double %.659.6.prol, 0x3FFE43A845D5AB9F
  %.664.6.prol = fadd double %.664.5.prol, %.662.6.prol
  %gep519.7.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.7.idx
  %.659.7.prol = load double, ptr %gep519.7.prol, align 8
  %.662.7.prol = fmul double %.659.7.prol, 0x4017346ECF96AF43
  %47 = fsub double %.664.6.prol, %.662.7.prol
  %gep519.8.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.8.idx
  %.659.8.prol = load double, ptr %gep519.8.prol, align 8
  %.662.8.prol = fmul double %.659.8.prol, 0x3FD3EA1DF2F0EB98
  %.664.8.prol = fadd double %47, %.662.8.prol
  %gep519.9.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.9.idx
  %.659.9.prol = load double, ptr %gep519.9.prol, align 8
  %.662.9.prol = fmul double %.659.9.prol, 0x3FC37A028F43B002
  %48 = fsub double %.664.8.prol, %.662.9.prol
  %gep519.10.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.10.idx
  %.659.10.prol = load double, ptr %gep519.10.prol, align 8
  %.662.10.prol = fmul double %.659.10.prol, 0x3FC9C657697FE72D
  %.664.10.prol = fadd double %48, %.662.10.prol
  %gep519.11.prol = getelementptr i8, ptr %invariant.gep.prol, i64 %gep519.11.idx
  %.659.11.prol = load double, ptr %gep519.11.prol, align 8
  %.662.11.prol = fmul double %.659.11.prol, 0x3FA6E44F50AB6BC2
  %.664.11.prol = fadd double %.664.10.prol, %.662.11.prol
  %49 = getelementptr double, ptr %arg.y.4, i64 %.394521526.ph
  %.702.prol = load double, ptr %49, align 8
  %.705.prol = fmul double %arg.h, %.664.11.prol
  %.708.prol = fadd double %.702.prol, %.705.prol
  %50 = getelementptr double, ptr %arg.ynew.4, i64 %.394521526.ph
  store double %.708.prol, ptr %50, align 8
  br label %B172.endif.endif.prol.loopexit

B172.endif.endif.prol.loopexit:                   ; preds = %B172.endif.endif.prol, %B172.endif.endif.preheader70
  %.394521526.unr = phi i64 [ %.394521526.ph, %B172.endif.endif.preheader70 ], [ %.neg, %B172.endif.endif.prol ]
  %51 = icmp eq i64 %arg.y.2, %.neg
  br i1 %51, label %B314, label %B172.endif.endif.preheader76

B172.endif.endif.preheader76:                     ; preds = %B172.endif.endif.prol.loopexit
  %scevgep91 = getelementptr i8, ptr %arg.K.4, i64 8
  %52 = shl i64 %arg.K.5.1, 3
  br label %B172.endif.endif

B172.endif.endif:                                 ; preds = %B172.endif.endif, %B172.endif.endif.preheader76
  %.394521526 = phi i64 [ %.401.1, %B172.endif.endif ], [ %.394521526.unr, %B172.endif.endif.preheader76 ]
  %53 = shl i64 %.394521526, 3
  %scevgep92 = getelementptr i8, ptr %scevgep91, i64 %53
  %scevgep93 = getelementptr i8, ptr %scevgep92, i64 -8
  %.659 = load double, ptr %scevgep93, align 8
  %.662 = fmul double %.659, 0x3FABCC6368D1177C
  %.664 = fadd double %.662, 0.000000e+00
  %scevgep103 = getelementptr i8, ptr %scevgep93, i64 %52
  %sunkaddr75 = mul i64 %arg.K.5.1, 8
  %sunkaddr76 = getelementptr i8, ptr %scevgep92, i64 %sunkaddr75
  %sunkaddr77 = getelementptr i8, ptr %sunkaddr76, i64 -8
  %.659.1 = load double, ptr %sunkaddr77, align 8
  %.662.1 = fmul double %.659.1, 0.000000e+00
  %.664.1 = fadd double %.664, %.662.1
  %scevgep104 = getelementptr i8, ptr %scevgep103, i64 %52
  %sunkaddr78 = mul i64 %arg.K.5.1, 8
  %sunkaddr79 = getelementptr i8, ptr %scevgep103, i64 %sunkaddr78
  %.659.2 = load double, ptr %sunkaddr79, align 8
  %.662.2 = fmul double %.659.2, 0.000000e+00
  %.664.2 = fadd double %.664.1, %.662.2
  %scevgep105 = getelementptr i8, ptr %scevgep104, i64 %52
  %sunkaddr80 = mul i64 %arg.K.5.1, 8
  %sunkaddr81 = getelementptr i8, ptr %scevgep104, i64 %sunkaddr80
  %.659.3 = load double, ptr %sunkaddr81, align 8
  %.662.3 = fmul double %.659.3, 0.000000e+00
  %.664.3 = fadd double %.664.2, %.662.3
  %scevgep106 = getelementptr i8, ptr %scevgep105, i64 %52
  %sunkaddr82 = mul i64 %arg.K.5.1, 8
  %sunkaddr83 = getelementptr i8, ptr %scevgep105, i64 %sunkaddr82
  %.659.4 = load double, ptr %sunkaddr83, align 8
  %.662.4 = fmul double %.659.4, 0.000000e+00
  %.664.4 = fadd double %.664.3, %.662.4
  %scevgep107 = getelementptr i8, ptr %scevgep106, i64 %52
  %sunkaddr84 = mul i64 %arg.K.5.1, 8
  %sunkaddr85 = getelementptr i8, ptr %scevgep106, i64 %sunkaddr84
  %.659.5 = load double, ptr %sunkaddr85, align 8
  %.662.5 = fmul double %.659.5, 0x4011CD1ED2AD5AE2
  %.664.5 = fadd double %.664.4, %.662.5
  %scevgep108 = getelementptr i8, ptr %scevgep107, i64 %52
  %sunkaddr86 = mul i64 %arg.K.5.1, 8
  %sunkaddr87 = getelementptr i8, ptr %scevgep107, i64 %sunkaddr86
  %.659.6 = load double, ptr %sunkaddr87, align 8
  %.662.6 = fmul double %.659.6, 0x3FFE43A845D5AB9F
  %.664.6 = fadd double %.664.5, %.662.6
  %scevgep109 = getelementptr i8, ptr %scevgep108, i64 %52
  %sunkaddr88 = mul i64 %arg.K.5.1, 8
  %sunkaddr89 = getelementptr i8, ptr %scevgep108, i64 %sunkaddr88
  %.659.7 = load double, ptr %sunkaddr89, align 8
  %.662.7 = fmul double %.659.7, 0x4017346ECF96AF43
  %54 = fsub double %.664.6, %.662.7
  %scevgep110 = getelementptr i8, ptr %scevgep109, i64 %52
  %sunkaddr90 = mul i64 %arg.K.5.1, 8
  %sunkaddr91 = getelementptr i8, ptr %scevgep109, i64 %sunkaddr90
  %.659.8 = load double, ptr %sunkaddr91, align 8
  %.662.8 = fmul double %.659.8, 0x3FD3EA1DF2F0EB98
  %.664.8 = fadd double %54, %.662.8
  %scevgep111 = getelementptr i8, ptr %scevgep110, i64 %52
  %sunkaddr92 = mul i64 %arg.K.5.1, 8
  %sunkaddr93 = getelementptr i8, ptr %scevgep110, i64 %sunkaddr92
  %.659.9 = load double, ptr %sunkaddr93, align 8
  %.662.9 = fmul double %.659.9, 0x3FC37A028F43B002
  %55 = fsub double %.664.8, %.662.9
  %scevgep112 = getelementptr i8, ptr %scevgep111, i64 %52
  %sunkaddr94 = mul i64 %arg.K.5.1, 8
  %sunkaddr95 = getelementptr i8, ptr %scevgep111, i64 %sunkaddr94
  %.659.10 = load double, ptr %sunkaddr95, align 8
  %.662.10 = fmul double %.659.10, 0x3FC9C657697FE72D
  %.664.10 = fadd double %55, %.662.10
  %sunkaddr = mul i64 %arg.K.5.1, 8
  %sunkaddr30 = getelementptr i8, ptr %scevgep112, i64 %sunkaddr
  %.659.11 = load double, ptr %sunkaddr30, align 8
  %.662.11 = fmul double %.659.11, 0x3FA6E44F50AB6BC2
  %.664.11 = fadd double %.664.10, %.662.11
  %sunkaddr31 = mul i64 %.394521526, 8
  %sunkaddr32 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr31
  %.702 = load double, ptr %sunkaddr32, align 8
  %.705 = fmul double %arg.h, %.664.11
  %.708 = fadd double %.702, %.705
  %sunkaddr33 = mul i64 %.394521526, 8
  %sunkaddr34 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr33
  store double %.708, ptr %sunkaddr34, align 8
  %.659.172 = load double, ptr %scevgep92, align 8
  %.662.173 = fmul double %.659.172, 0x3FABCC6368D1177C
  %.664.174 = fadd double %.662.173, 0.000000e+00
  %sunkaddr35 = mul i64 %arg.K.5.1, 8
  %sunkaddr36 = getelementptr i8, ptr %scevgep92, i64 %sunkaddr35
  %.659.1.1 = load double, ptr %sunkaddr36, align 8
  %.662.1.1 = fmul double %.659.1.1, 0.000000e+00
  %.664.1.1 = fadd double %.664.174, %.662.1.1
  %sunkaddr37 = mul i64 %arg.K.5.1, 8
  %sunkaddr38 = getelementptr i8, ptr %scevgep103, i64 %sunkaddr37
  %sunkaddr39 = getelementptr i8, ptr %sunkaddr38, i64 8
  %.659.2.1 = load double, ptr %sunkaddr39, align 8
  %.662.2.1 = fmul double %.659.2.1, 0.000000e+00
  %.664.2.1 = fadd double %.664.1.1, %.662.2.1
  %sunkaddr40 = mul i64 %arg.K.5.1, 8
  %sunkaddr41 = getelementptr i8, ptr %scevgep104, i64 %sunkaddr40
  %sunkaddr42 = getelementptr i8, ptr %sunkaddr41, i64 8
  %.659.3.1 = load double, ptr %sunkaddr42, align 8
  %.662.3.1 = fmul double %.659.3.1, 0.000000e+00
  %.664.3.1 = fadd double %.664.2.1, %.662.3.1
  %sunkaddr43 = mul i64 %arg.K.5.1, 8
  %sunkaddr44 = getelementptr i8, ptr %scevgep105, i64 %sunkaddr43
  %sunkaddr45 = getelementptr i8, ptr %sunkaddr44, i64 8
  %.659.4.1 = load double, ptr %sunkaddr45, align 8
  %.662.4.1 = fmul double %.659.4.1, 0.000000e+00
  %.664.4.1 = fadd double %.664.3.1, %.662.4.1
  %sunkaddr46 = mul i64 %arg.K.5.1, 8
  %sunkaddr47 = getelementptr i8, ptr %scevgep106, i64 %sunkaddr46
  %sunkaddr48 = getelementptr i8, ptr %sunkaddr47, i64 8
  %.659.5.1 = load double, ptr %sunkaddr48, align 8
  %.662.5.1 = fmul double %.659.5.1, 0x4011CD1ED2AD5AE2
  %.664.5.1 = fadd double %.664.4.1, %.662.5.1
  %sunkaddr49 = mul i64 %arg.K.5.1, 8
  %sunkaddr50 = getelementptr i8, ptr %scevgep107, i64 %sunkaddr49
  %sunkaddr51 = getelementptr i8, ptr %sunkaddr50, i64 8
  %.659.6.1 = load double, ptr %sunkaddr51, align 8
  %.662.6.1 = fmul double %.659.6.1, 0x3FFE43A845D5AB9F
  %.664.6.1 = fadd double %.664.5.1, %.662.6.1
  %sunkaddr52 = mul i64 %arg.K.5.1, 8
  %sunkaddr53 = getelementptr i8, ptr %scevgep108, i64 %sunkaddr52
  %sunkaddr54 = getelementptr i8, ptr %sunkaddr53, i64 8
  %.659.7.1 = load double, ptr %sunkaddr54, align 8
  %.662.7.1 = fmul double %.659.7.1, 0x4017346ECF96AF43
  %56 = fsub double %.664.6.1, %.662.7.1
  %sunkaddr55 = mul i64 %arg.K.5.1, 8
  %sunkaddr56 = getelementptr i8, ptr %scevgep109, i64 %sunkaddr55
  %sunkaddr57 = getelementptr i8, ptr %sunkaddr56, i64 8
  %.659.8.1 = load double, ptr %sunkaddr57, align 8
  %.662.8.1 = fmul double %.659.8.1, 0x3FD3EA1DF2F0EB98
  %.664.8.1 = fadd double %56, %.662.8.1
  %sunkaddr58 = mul i64 %arg.K.5.1, 8
  %sunkaddr59 = getelementptr i8, ptr %scevgep110, i64 %sunkaddr58
  %sunkaddr60 = getelementptr i8, ptr %sunkaddr59, i64 8
  %.659.9.1 = load double, ptr %sunkaddr60, align 8
  %.662.9.1 = fmul double %.659.9.1, 0x3FC37A028F43B002
  %57 = fsub double %.664.8.1, %.662.9.1
  %sunkaddr61 = mul i64 %arg.K.5.1, 8
  %sunkaddr62 = getelementptr i8, ptr %scevgep111, i64 %sunkaddr61
  %sunkaddr63 = getelementptr i8, ptr %sunkaddr62, i64 8
  %.659.10.1 = load double, ptr %sunkaddr63, align 8
  %.662.10.1 = fmul double %.659.10.1, 0x3FC9C657697FE72D
  %.664.10.1 = fadd double %57, %.662.10.1
  %sunkaddr64 = mul i64 %arg.K.5.1, 8
  %sunkaddr65 = getelementptr i8, ptr %scevgep112, i64 %sunkaddr64
  %sunkaddr66 = getelementptr i8, ptr %sunkaddr65, i64 8
  %.659.11.1 = load double, ptr %sunkaddr66, align 8
  %.662.11.1 = fmul double %.659.11.1, 0x3FA6E44F50AB6BC2
  %.664.11.1 = fadd double %.664.10.1, %.662.11.1
  %.401.1 = add nuw nsw i64 %.394521526, 2
  %sunkaddr67 = mul i64 %.394521526, 8
  %sunkaddr68 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr67
  %sunkaddr69 = getelementptr i8, ptr %sunkaddr68, i64 8
  %.702.1 = load double, ptr %sunkaddr69, align 8
  %.705.1 = fmul double %arg.h, %.664.11.1
  %.708.1 = fadd double %.702.1, %.705.1
  %sunkaddr70 = mul i64 %.394521526, 8
  %sunkaddr71 = getelementptr i8, ptr %arg.ynew.4, i64 %sunkaddr70
  %sunkaddr72 = getelementptr i8, ptr %sunkaddr71, i64 8
  store double %.708.1, ptr %sunkaddr72, align 8
  %exitcond587.not.1 = icmp eq i64 %arg.y.2, %.401.1
  br i1 %exitcond587.not.1, label %B314, label %B172.endif.endif, !llvm.loop !89

B314.if:                                          ; preds = %B314
  %.833 = icmp eq ptr %arg.f.0, null
  br i1 %.833, label %B314.if.if, label %B314.if.endif, !prof !0

B314.else:                                        ; preds = %B314
  store double 0.000000e+00, ptr %.880, align 8
  %.890 = call i32 %arg.f.2(ptr nonnull %.880, ptr nonnull %excinfo.3, ptr %arg.ynew.0, ptr %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.786, i64 %arg.K.5.1, i64 %arg.K.6.1)
  %.900 = load double, ptr %.880, align 8
  switch i32 %.890, label %B314.else.if.if [
    i32 -2, label %B314.endif.endif.endif
    i32 0, label %B314.endif.endif.endif
  ], !prof !4

B314.if.if:                                       ; preds = %B314.if
  %.835 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers2rk11dop853_stepB3v89B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEdd, align 8
  %.836 = icmp eq ptr %.835, null
  br i1 %.836, label %B314.if.if.if, label %B314.if.if.endif, !prof !0

B314.if.endif:                                    ; preds = %B314.if.if.endif.endif, %B314.if
  %fptr_of_f.0 = phi ptr [ %.866, %B314.if.if.endif.endif ], [ %arg.f.0, %B314.if ]
  %.876 = call double %fptr_of_f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.818.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.819.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.814.fca.6.0.insert)
  br label %B314.endif.endif.endif

B314.if.if.if:                                    ; preds = %B314.if.if
  store ptr @.const.picklebuf.f77baf611f08f85307c33ca008225eb68c830d48, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B314.if.if.endif:                                 ; preds = %B314.if.if
  call void @numba_gil_ensure(ptr nonnull %.845)
  %.848 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.38)
  %.849 = call ptr @PyObject_GetAttrString(ptr %.848, ptr nonnull @.const._get_wrapper_address.39)
  call void @Py_DecRef(ptr %.848)
  %.857 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.40, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.41)
  %.858 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.849, ptr %arg.f.1, ptr %.857, ptr null)
  %.859 = icmp eq ptr %.858, null
  br i1 %.859, label %B314.if.if.endif.if, label %B314.if.if.endif.endif, !prof !0

B314.if.if.endif.if:                              ; preds = %B314.if.if.endif
  store ptr @.const.picklebuf.2618a0875071fc91168fe680494fc2bbf1957ea8, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B314.if.if.endif.endif:                           ; preds = %B314.if.if.endif
  %.866 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.858)
  call void @Py_DecRef(ptr nonnull %.858)
  call void @numba_gil_release(ptr nonnull %.845)
  br label %B314.if.endif

B314.else.if.if:                                  ; preds = %B314.else
  %.898 = icmp sgt i32 %.890, 0
  %.891 = load ptr, ptr %excinfo.3, align 8
  %.899 = select i1 %.898, ptr %.891, ptr undef
  store ptr %.899, ptr %excinfo, align 8
  br label %common.ret

B314.endif.endif.endif:                           ; preds = %B314.if.endif, %B314.else, %B314.else
  %.827.0 = phi double [ %.876, %B314.if.endif ], [ %.900, %B314.else ], [ %.900, %B314.else ]
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.K.0)
  %.12.i12 = fcmp olt double %.827.0, %.13.i
  %.13.i13 = select i1 %.12.i12, double %.827.0, double %.13.i
  %.1043557.not = icmp slt i64 %arg.y.2, 1
  br i1 %.1043557.not, label %B766, label %B430.endif.endif.preheader

B430.endif.endif.preheader:                       ; preds = %B314.endif.endif.endif
  %58 = shl i64 %arg.K.5.1, 3
  br label %B600.endif

B600.endif:                                       ; preds = %B600.endif.endif, %B430.endif.endif.preheader
  %e3.2.0561 = phi double [ %.1622, %B600.endif.endif ], [ 0.000000e+00, %B430.endif.endif.preheader ]
  %e5.2.0560 = phi double [ %.1583, %B600.endif.endif ], [ 0.000000e+00, %B430.endif.endif.preheader ]
  %.1049544558 = phi i64 [ %.1056, %B600.endif.endif ], [ 0, %B430.endif.endif.preheader ]
  %59 = shl i64 %.1049544558, 3
  %scevgep78 = getelementptr i8, ptr %arg.y.4, i64 %59
  %.1479 = load double, ptr %scevgep78, align 8
  %.1480 = call double @llvm.fabs.f64(double %.1479)
  %scevgep77 = getelementptr i8, ptr %arg.ynew.4, i64 %59
  %.1511 = load double, ptr %scevgep77, align 8
  %.1514 = call double @llvm.fabs.f64(double %.1511)
  %.12.i14 = fcmp ogt double %.1514, %.1480
  %.13.i15 = select i1 %.12.i14, double %.1514, double %.1480
  %.1544 = fmul double %arg.rtol, %.13.i15
  %.1546 = fadd double %arg.atol, %.1544
  %.1548 = fcmp oeq double %.1546, 0.000000e+00
  br i1 %.1548, label %B600.endif.if, label %B600.endif.endif, !prof !0

B600.endif.if:                                    ; preds = %B600.endif
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.42, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B600.endif.endif:                                 ; preds = %B600.endif
  %.1056 = add nuw nsw i64 %.1049544558, 1
  %60 = shl i64 %.1049544558, 3
  %scevgep8 = getelementptr i8, ptr %arg.K.4, i64 %60
  %.1318 = load double, ptr %scevgep8, align 8
  %.1439 = fmul double %.1318, 0x3FC84B641FBFA1F1
  %61 = fsub double 0.000000e+00, %.1439
  %scevgep9 = getelementptr i8, ptr %scevgep8, i64 %58
  %sunkaddr96 = mul i64 %arg.K.5.1, 8
  %sunkaddr97 = getelementptr i8, ptr %scevgep8, i64 %sunkaddr96
  %.1318.1 = load double, ptr %sunkaddr97, align 8
  %.1321.1 = fmul double %.1318.1, 0.000000e+00
  %.1441.1 = fadd double %61, %.1321.1
  %scevgep10 = getelementptr i8, ptr %scevgep9, i64 %58
  %sunkaddr98 = mul i64 %arg.K.5.1, 8
  %sunkaddr99 = getelementptr i8, ptr %scevgep9, i64 %sunkaddr98
  %.1318.2 = load double, ptr %sunkaddr99, align 8
  %.1321.2 = fmul double %.1318.2, 0.000000e+00
  %.1441.2 = fadd double %.1441.1, %.1321.2
  %scevgep11 = getelementptr i8, ptr %scevgep10, i64 %58
  %sunkaddr100 = mul i64 %arg.K.5.1, 8
  %sunkaddr101 = getelementptr i8, ptr %scevgep10, i64 %sunkaddr100
  %.1318.3 = load double, ptr %sunkaddr101, align 8
  %.1321.3 = fmul double %.1318.3, 0.000000e+00
  %.1441.3 = fadd double %.1441.2, %.1321.3
  %scevgep12 = getelementptr i8, ptr %scevgep11, i64 %58
  %sunkaddr102 = mul i64 %arg.K.5.1, 8
  %sunkaddr103 = getelementptr i8, ptr %scevgep11, i64 %sunkaddr102
  %.1318.4 = load double, ptr %sunkaddr103, align 8
  %.1321.4 = fmul double %.1318.4, 0.000000e+00
  %.1441.4 = fadd double %.1441.3, %.1321.4
  %scevgep13 = getelementptr i8, ptr %scevgep12, i64 %58
  %sunkaddr104 = mul i64 %arg.K.5.1, 8
  %sunkaddr105 = getelementptr i8, ptr %scevgep12, i64 %sunkaddr104
  %.1318.5 = load double, ptr %sunkaddr105, align 8
  %.1439.5 = fmul double %.1318.5, 0x4011CD1ED2AD5AE2
  %.1441.5 = fadd double %.1441.4, %.1439.5
  %scevgep14 = getelementptr i8, ptr %scevgep13, i64 %58
  %sunkaddr106 = mul i64 %arg.K.5.1, 8
  %sunkaddr107 = getelementptr i8, ptr %scevgep13, i64 %sunkaddr106
  %.1318.6 = load double, ptr %sunkaddr107, align 8
  %.1439.6 = fmul double %.1318.6, 0x3FFE43A845D5AB9F
  %.1441.6 = fadd double %.1441.5, %.1439.6
  %scevgep15 = getelementptr i8, ptr %scevgep14, i64 %58
  %sunkaddr108 = mul i64 %arg.K.5.1, 8
  %sunkaddr109 = getelementptr i8, ptr %scevgep14, i64 %sunkaddr108
  %.1318.7 = load double, ptr %sunkaddr109, align 8
  %.1439.7 = fmul double %.1318.7, 0x4017346ECF96AF43
  %62 = fsub double %.1441.6, %.1439.7
  %scevgep16 = getelementptr i8, ptr %scevgep15, i64 %58
  %sunkaddr110 = mul i64 %arg.K.5.1, 8
  %sunkaddr111 = getelementptr i8, ptr %scevgep15, i64 %sunkaddr110
  %.1318.8 = load double, ptr %sunkaddr111, align 8
  %.1439.8 = fmul double %.1318.8, 0x3FDB0D3A26ABB716
  %63 = fsub double %62, %.1439.8
  %scevgep17 = getelementptr i8, ptr %scevgep16, i64 %58
  %sunkaddr112 = mul i64 %arg.K.5.1, 8
  %sunkaddr113 = getelementptr i8, ptr %scevgep16, i64 %sunkaddr112
  %.1318.9 = load double, ptr %sunkaddr113, align 8
  %.1439.9 = fmul double %.1318.9, 0x3FC37A028F43B002
  %64 = fsub double %63, %.1439.9
  %scevgep18 = getelementptr i8, ptr %scevgep17, i64 %58
  %sunkaddr114 = mul i64 %arg.K.5.1, 8
  %sunkaddr115 = getelementptr i8, ptr %scevgep17, i64 %sunkaddr114
  %.1318.10 = load double, ptr %sunkaddr115, align 8
  %.1439.10 = fmul double %.1318.10, 0x3FC9C657697FE72D
  %.1441.10 = fadd double %64, %.1439.10
  %scevgep19 = getelementptr i8, ptr %scevgep18, i64 %58
  %sunkaddr116 = mul i64 %arg.K.5.1, 8
  %sunkaddr117 = getelementptr i8, ptr %scevgep18, i64 %sunkaddr116
  %.1318.11 = load double, ptr %sunkaddr117, align 8
  %.1439.11 = fmul double %.1318.11, 0x3F9732080AC040ED
  %.1441.11 = fadd double %.1441.10, %.1439.11
  %sunkaddr73 = mul i64 %arg.K.5.1, 8
  %sunkaddr74 = getelementptr i8, ptr %scevgep19, i64 %sunkaddr73
  %.1318.12 = load double, ptr %sunkaddr74, align 8
  %.1321.12 = fmul double %.1318.12, 0.000000e+00
  %.1441.12 = fadd double %.1441.11, %.1321.12
  %.1321 = fmul double %.1318, 0x3F8ADEAEA1607E1A
  %.1323 = fadd double %.1321, 0.000000e+00
  %.1323.1 = fadd double %.1323, %.1321.1
  %.1323.2 = fadd double %.1323.1, %.1321.2
  %.1323.3 = fadd double %.1323.2, %.1321.3
  %.1323.4 = fadd double %.1323.3, %.1321.4
  %.1321.5 = fmul double %.1318.5, 0x3FF39A3DA55AB5C3
  %65 = fsub double %.1323.4, %.1321.5
  %.1321.6 = fmul double %.1318.6, 0x3FDFBA83BEDE8A72
  %66 = fsub double %65, %.1321.6
  %.1321.7 = fmul double %.1318.7, 0x3FFAA149F7EDA509
  %.1323.7 = fadd double %66, %.1321.7
  %.1321.8 = fmul double %.1318.8, 0x3FD66BC9B10E7E71
  %67 = fsub double %.1323.7, %.1321.8
  %.1321.9 = fmul double %.1318.9, 0x3FD56330D0783989
  %.1323.9 = fadd double %67, %.1321.9
  %.1321.10 = fmul double %.1318.10, 0x3FB4F8EB54A31435
  %.1323.10 = fadd double %.1323.9, %.1321.10
  %.1321.11 = fmul double %.1318.11, 0x3F96E44F50AB6BC2
  %68 = fsub double %.1323.10, %.1321.11
  %.1323.12 = fadd double %68, %.1321.12
  %.1555 = fdiv double %.1323.12, %.1546
  %.1594 = fdiv double %.1441.12, %.1546
  %.147.i25 = fmul double %.1594, %.1594
  %.147.i = fmul double %.1555, %.1555
  %.1583 = fadd double %e5.2.0560, %.147.i
  %.1622 = fadd double %e3.2.0561, %.147.i25
  %exitcond589.not = icmp eq i64 %arg.y.2, %.1056
  br i1 %exitcond589.not, label %B766, label %B600.endif

B798.if:                                          ; preds = %B798
  store ptr @.const.picklebuf.b28008a0f88bad5ff0f0243e84dab90cab19b366.42, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B798.endif:                                       ; preds = %B798
  %.1679 = call double @llvm.fabs.f64(double %arg.h)
  %.1683 = fmul double %.1679, %e5.2.0.lcssa
  %.1705 = fdiv double %.1683, %.1697
  store double %.1705, ptr %retptr, align 8
  %retptr.repack486 = getelementptr inbounds nuw i8, ptr %retptr, i64 8
  store double %.13.i13, ptr %retptr.repack486, align 8
  br label %common.ret
}

define linkonce_odr range(i32 -1, -2) i32 @_ZN6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.f.0, ptr %arg.f.1, ptr readonly captures(address_is_null) %arg.f.2, ptr readnone captures(none) %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, i64 %arg.s, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0) local_unnamed_addr {
B0.endif:
  %.703 = alloca i32, align 4
  store i32 0, ptr %.703, align 4
  %.738 = alloca double, align 8
  store double 0.000000e+00, ptr %.738, align 8
  %excinfo.1 = alloca ptr, align 8
  store ptr null, ptr %excinfo.1, align 8
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.K.0)
  tail call void @NRT_incref(ptr %arg.ytmp.0)
  %.165259.not = icmp slt i64 %arg.y.2, 1
  br i1 %.165259.not, label %B202, label %B50.endif.lr.ph

B50.endif.lr.ph:                                  ; preds = %B0.endif
  %.289245.not = icmp slt i64 %arg.s, 1
  br i1 %.289245.not, label %iter.check, label %B50.endif.us.preheader

B50.endif.us.preheader:                           ; preds = %B50.endif.lr.ph
  %const = bitcast i64 9223372036854775776 to i64
  %.idx = shl i64 %arg.s, 7
  %xtraiter = and i64 %arg.s, 7
  %const_mat = add i64 %const, 24
  %unroll_iter = and i64 %arg.s, %const_mat
  %0 = getelementptr i8, ptr @.const.array.data, i64 %.idx
  %scevgep78 = getelementptr i8, ptr %0, i64 56
  %1 = mul i64 %arg.K.5.1, 56
  %2 = shl i64 %arg.K.5.1, 6
  %3 = mul i64 %arg.K.5.1, 48
  %4 = mul i64 %arg.K.5.1, 40
  %5 = shl i64 %arg.K.5.1, 5
  %6 = mul i64 %arg.K.5.1, 24
  %7 = shl i64 %arg.K.5.1, 4
  %8 = shl i64 %arg.K.5.1, 3
  br label %B50.endif.us

B50.endif.us:                                     ; preds = %B86.B166_crit_edge.us, %B50.endif.us.preheader
  %lsr.iv94 = phi ptr [ %arg.K.4, %B50.endif.us.preheader ], [ %scevgep95, %B86.B166_crit_edge.us ]
  %.171254260.us = phi i64 [ 0, %B50.endif.us.preheader ], [ %.178.us, %B86.B166_crit_edge.us ]
  %9 = icmp ult i64 %arg.s, 8
  br i1 %9, label %B88.us.epil.preheader, label %B88.us.preheader

B88.us.preheader:                                 ; preds = %B50.endif.us
  br label %B88.us

B88.us:                                           ; preds = %B88.us.preheader, %B164.us.7
  %lsr.iv96 = phi ptr [ %scevgep97, %B164.us.7 ], [ %lsr.iv94, %B88.us.preheader ]
  %acc.2.1248.us = phi double [ %acc.3.2.us.7, %B164.us.7 ], [ 0.000000e+00, %B88.us.preheader ]
  %.295244246.us = phi i64 [ %.302.us.7, %B164.us.7 ], [ 0, %B88.us.preheader ]
  %10 = shl i64 %.295244246.us, 3
  %scevgep92 = getelementptr i8, ptr %scevgep78, i64 %10
  %scevgep93 = getelementptr i8, ptr %scevgep92, i64 -56
  %.416.us = load double, ptr %scevgep93, align 8
  %.428.us = fcmp une double %.416.us, 0.000000e+00
  br i1 %.428.us, label %B132.us, label %B164.us

B132.us:                                          ; preds = %B88.us
  %.485.us = load double, ptr %lsr.iv96, align 8
  %.489.us = fmul double %.416.us, %.485.us
  %.493.us = fadd double %acc.2.1248.us, %.489.us
  br label %B164.us

B164.us:                                          ; preds = %B132.us, %B88.us
  %acc.3.2.us = phi double [ %.493.us, %B132.us ], [ %acc.2.1248.us, %B88.us ]
  %11 = shl i64 %.295244246.us, 3
  %scevgep82 = getelementptr i8, ptr %scevgep78, i64 %11
  %scevgep83 = getelementptr i8, ptr %scevgep82, i64 -48
  %.416.us.1 = load double, ptr %scevgep83, align 8
  %.428.us.1 = fcmp une double %.416.us.1, 0.000000e+00
  br i1 %.428.us.1, label %B132.us.1, label %B164.us.1

B132.us.1:                                        ; preds = %B164.us
  %sunkaddr113 = getelementptr i8, ptr %lsr.iv96, i64 %8
  %.485.us.1 = load double, ptr %sunkaddr113, align 8
  %.489.us.1 = fmul double %.416.us.1, %.485.us.1
  %.493.us.1 = fadd double %acc.3.2.us, %.489.us.1
  br label %B164.us.1

B164.us.1:                                        ; preds = %B132.us.1, %B164.us
  %acc.3.2.us.1 = phi double [ %.493.us.1, %B132.us.1 ], [ %acc.3.2.us, %B164.us ]
  %12 = shl i64 %.295244246.us, 3
  %scevgep80 = getelementptr i8, ptr %scevgep78, i64 %12
  %scevgep81 = getelementptr i8, ptr %scevgep80, i64 -40
  %.416.us.2 = load double, ptr %scevgep81, align 8
  %.428.us.2 = fcmp une double %.416.us.2, 0.000000e+00
  br i1 %.428.us.2, label %B132.us.2, label %B164.us.2

B132.us.2:                                        ; preds = %B164.us.1
  %scevgep103 = getelementptr i8, ptr %lsr.iv96, i64 %7
  %.485.us.2 = load double, ptr %scevgep103, align 8
  %.489.us.2 = fmul double %.416.us.2, %.485.us.2
  %.493.us.2 = fadd double %acc.3.2.us.1, %.489.us.2
  br label %B164.us.2

B164.us.2:                                        ; preds = %B132.us.2, %B164.us.1
  %acc.3.2.us.2 = phi double [ %.493.us.2, %B132.us.2 ], [ %acc.3.2.us.1, %B164.us.1 ]
  %13 = shl i64 %.295244246.us, 3
  %scevgep77 = getelementptr i8, ptr %scevgep78, i64 %13
  %scevgep79 = getelementptr i8, ptr %scevgep77, i64 -32
  %.416.us.3 = load double, ptr %scevgep79, align 8
  %.428.us.3 = fcmp une double %.416.us.3, 0.000000e+00
  br i1 %.428.us.3, label %B132.us.3, label %B164.us.3

B132.us.3:                                        ; preds = %B164.us.2
  %scevgep102 = getelementptr i8, ptr %lsr.iv96, i64 %6
  %.485.us.3 = load double, ptr %scevgep102, align 8
  %.489.us.3 = fmul double %.416.us.3, %.485.us.3
  %.493.us.3 = fadd double %acc.3.2.us.2, %.489.us.3
  br label %B164.us.3

B164.us.3:                                        ; preds = %B132.us.3, %B164.us.2
  %acc.3.2.us.3 = phi double [ %.493.us.3, %B132.us.3 ], [ %acc.3.2.us.2, %B164.us.2 ]
  %14 = shl i64 %.295244246.us, 3
  %scevgep72 = getelementptr i8, ptr %scevgep78, i64 %14
  %scevgep74 = getelementptr i8, ptr %scevgep72, i64 -24
  %.416.us.4 = load double, ptr %scevgep74, align 8
  %.428.us.4 = fcmp une double %.416.us.4, 0.000000e+00
  br i1 %.428.us.4, label %B132.us.4, label %B164.us.4

B132.us.4:                                        ; preds = %B164.us.3
  %scevgep101 = getelementptr i8, ptr %lsr.iv96, i64 %5
  %.485.us.4 = load double, ptr %scevgep101, align 8
  %.489.us.4 = fmul double %.416.us.4, %.485.us.4
  %.493.us.4 = fadd double %acc.3.2.us.3, %.489.us.4
  br label %B164.us.4

B164.us.4:                                        ; preds = %B132.us.4, %B164.us.3
  %acc.3.2.us.4 = phi double [ %.493.us.4, %B132.us.4 ], [ %acc.3.2.us.3, %B164.us.3 ]
  %15 = shl i64 %.295244246.us, 3
  %scevgep68 = getelementptr i8, ptr %scevgep78, i64 %15
  %scevgep70 = getelementptr i8, ptr %scevgep68, i64 -16
  %.416.us.5 = load double, ptr %scevgep70, align 8
  %.428.us.5 = fcmp une double %.416.us.5, 0.000000e+00
  br i1 %.428.us.5, label %B132.us.5, label %B164.us.5

B132.us.5:                                        ; preds = %B164.us.4
  %scevgep100 = getelementptr i8, ptr %lsr.iv96, i64 %4
  %.485.us.5 = load double, ptr %scevgep100, align 8
  %.489.us.5 = fmul double %.416.us.5, %.485.us.5
  %.493.us.5 = fadd double %acc.3.2.us.4, %.489.us.5
  br label %B164.us.5

B164.us.5:                                        ; preds = %B132.us.5, %B164.us.4
  %acc.3.2.us.5 = phi double [ %.493.us.5, %B132.us.5 ], [ %acc.3.2.us.4, %B164.us.4 ]
  %16 = shl i64 %.295244246.us, 3
  %scevgep64 = getelementptr i8, ptr %scevgep78, i64 %16
  %scevgep66 = getelementptr i8, ptr %scevgep64, i64 -8
  %.416.us.6 = load double, ptr %scevgep66, align 8
  %.428.us.6 = fcmp une double %.416.us.6, 0.000000e+00
  br i1 %.428.us.6, label %B132.us.6, label %B164.us.6

B132.us.6:                                        ; preds = %B164.us.5
  %scevgep99 = getelementptr i8, ptr %lsr.iv96, i64 %3
  %.485.us.6 = load double, ptr %scevgep99, align 8
  %.489.us.6 = fmul double %.416.us.6, %.485.us.6
  %.493.us.6 = fadd double %acc.3.2.us.5, %.489.us.6
  br label %B164.us.6

B164.us.6:                                        ; preds = %B132.us.6, %B164.us.5
  %acc.3.2.us.6 = phi double [ %.493.us.6, %B132.us.6 ], [ %acc.3.2.us.5, %B164.us.5 ]
  %.302.us.7 = add nuw nsw i64 %.295244246.us, 8
  %sunkaddr = mul i64 %.295244246.us, 8
  %sunkaddr86 = getelementptr i8, ptr %scevgep78, i64 %sunkaddr
  %.416.us.7 = load double, ptr %sunkaddr86, align 8
  %.428.us.7 = fcmp une double %.416.us.7, 0.000000e+00
  br i1 %.428.us.7, label %B132.us.7, label %B164.us.7

B132.us.7:                                        ; preds = %B164.us.6
  %scevgep98 = getelementptr i8, ptr %lsr.iv96, i64 %1
  %.485.us.7 = load double, ptr %scevgep98, align 8
  %.489.us.7 = fmul double %.416.us.7, %.485.us.7
  %.493.us.7 = fadd double %acc.3.2.us.6, %.489.us.7
  br label %B164.us.7

B164.us.7:                                        ; preds = %B132.us.7, %B164.us.6
  %acc.3.2.us.7 = phi double [ %.493.us.7, %B132.us.7 ], [ %acc.3.2.us.6, %B164.us.6 ]
  %scevgep97 = getelementptr i8, ptr %lsr.iv96, i64 %2
  %niter.ncmp.7 = icmp eq i64 %unroll_iter, %.302.us.7
  br i1 %niter.ncmp.7, label %B86.B166_crit_edge.us.unr-lcssa, label %B88.us

B86.B166_crit_edge.us.unr-lcssa:                  ; preds = %B164.us.7
  %17 = icmp eq i64 %xtraiter, 0
  br i1 %17, label %B86.B166_crit_edge.us, label %B88.us.epil.preheader

B88.us.epil.preheader:                            ; preds = %B86.B166_crit_edge.us.unr-lcssa, %B50.endif.us
  %acc.2.1248.us.epil.init = phi double [ 0.000000e+00, %B50.endif.us ], [ %acc.3.2.us.7, %B86.B166_crit_edge.us.unr-lcssa ]
  %.295244246.us.epil.init = phi i64 [ 0, %B50.endif.us ], [ %unroll_iter, %B86.B166_crit_edge.us.unr-lcssa ]
  %18 = mul i64 %.295244246.us.epil.init, %8
  %scevgep105 = getelementptr i8, ptr %lsr.iv94, i64 %18
  %19 = shl i64 %.295244246.us.epil.init, 3
  %scevgep109 = getelementptr i8, ptr %0, i64 %19
  br label %B88.us.epil

B88.us.epil:                                      ; preds = %B164.us.epil, %B88.us.epil.preheader
  %lsr.iv106 = phi ptr [ %scevgep107, %B164.us.epil ], [ %scevgep105, %B88.us.epil.preheader ]
  %acc.2.1248.us.epil = phi double [ %acc.3.2.us.epil, %B164.us.epil ], [ %acc.2.1248.us.epil.init, %B88.us.epil.preheader ]
  %epil.iter = phi i64 [ %epil.iter.next, %B164.us.epil ], [ 0, %B88.us.epil.preheader ]
  %20 = shl i64 %epil.iter, 3
  %scevgep76 = getelementptr i8, ptr %scevgep109, i64 %20
  %.416.us.epil = load double, ptr %scevgep76, align 8
  %.428.us.epil = fcmp une double %.416.us.epil, 0.000000e+00
  br i1 %.428.us.epil, label %B132.us.epil, label %B164.us.epil

B132.us.epil:                                     ; preds = %B88.us.epil
  %.485.us.epil = load double, ptr %lsr.iv106, align 8
  %.489.us.epil = fmul double %.416.us.epil, %.485.us.epil
  %.493.us.epil = fadd double %acc.2.1248.us.epil, %.489.us.epil
  br label %B164.us.epil

B164.us.epil:                                     ; preds = %B132.us.epil, %B88.us.epil
  %acc.3.2.us.epil = phi double [ %.493.us.epil, %B132.us.epil ], [ %acc.2.1248.us.epil, %B88.us.epil ]
  %epil.iter.next = add i64 %epil.iter, 1
  %scevgep107 = getelementptr i8, ptr %lsr.iv106, i64 %8
  %epil.iter.cmp.not = icmp eq i64 %xtraiter, %epil.iter.next
  br i1 %epil.iter.cmp.not, label %B86.B166_crit_edge.us, label %B88.us.epil, !llvm.loop !90

B86.B166_crit_edge.us:                            ; preds = %B164.us.epil, %B86.B166_crit_edge.us.unr-lcssa
  %acc.3.2.us.lcssa = phi double [ %acc.3.2.us.7, %B86.B166_crit_edge.us.unr-lcssa ], [ %acc.3.2.us.epil, %B164.us.epil ]
  %.178.us = add nuw nsw i64 %.171254260.us, 1
  %21 = getelementptr double, ptr %arg.y.4, i64 %.171254260.us
  %.543.us = load double, ptr %21, align 8
  %.546.us = fmul double %arg.h, %acc.3.2.us.lcssa
  %.549.us = fadd double %.546.us, %.543.us
  %22 = getelementptr double, ptr %arg.ytmp.4, i64 %.171254260.us
  store double %.549.us, ptr %22, align 8
  %scevgep95 = getelementptr i8, ptr %lsr.iv94, i64 8
  %exitcond270.not = icmp eq i64 %arg.y.2, %.178.us
  br i1 %exitcond270.not, label %B202, label %B50.endif.us

iter.check:                                       ; preds = %B50.endif.lr.ph
  %23 = ptrtoint ptr %arg.ytmp.4 to i64
  %24 = ptrtoint ptr %arg.y.4 to i64
  %.546 = fmul double %arg.h, 0.000000e+00
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 4
  %25 = sub i64 %23, %24
  %diff.check = icmp ult i64 %25, 256
  %or.cond = select i1 %min.iters.check, i1 true, i1 %diff.check
  br i1 %or.cond, label %B50.endif.preheader, label %vector.main.loop.iter.check

vector.main.loop.iter.check:                      ; preds = %iter.check
  %const84 = bitcast i64 9223372036854775776 to i64
  %min.iters.check8 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check8, label %vec.epilog.ph, label %vector.ph

vector.ph:                                        ; preds = %vector.main.loop.iter.check
  %n.vec = and i64 %arg.y.2, %const84
  %broadcast.splatinsert = insertelement <8 x double> poison, double %.546, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %sunkaddr87 = mul i64 %index, 8
  %sunkaddr88 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr87
  %wide.load = load <8 x double>, ptr %sunkaddr88, align 8
  %sunkaddr89 = mul i64 %index, 8
  %sunkaddr90 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr89
  %sunkaddr91 = getelementptr i8, ptr %sunkaddr90, i64 64
  %wide.load9 = load <8 x double>, ptr %sunkaddr91, align 8
  %sunkaddr92 = mul i64 %index, 8
  %sunkaddr93 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr92
  %sunkaddr94 = getelementptr i8, ptr %sunkaddr93, i64 128
  %wide.load10 = load <8 x double>, ptr %sunkaddr94, align 8
  %sunkaddr95 = mul i64 %index, 8
  %sunkaddr96 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr95
  %sunkaddr97 = getelementptr i8, ptr %sunkaddr96, i64 192
  %wide.load11 = load <8 x double>, ptr %sunkaddr97, align 8
  %26 = fadd <8 x double> %broadcast.splat, %wide.load
  %27 = fadd <8 x double> %broadcast.splat, %wide.load9
  %28 = fadd <8 x double> %broadcast.splat, %wide.load10
  %29 = fadd <8 x double> %broadcast.splat, %wide.load11
  %sunkaddr98 = mul i64 %index, 8
  %sunkaddr99 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr98
  store <8 x double> %26, ptr %sunkaddr99, align 8
  %sunkaddr100 = mul i64 %index, 8
  %sunkaddr101 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr100
  %sunkaddr103 = getelementptr i8, ptr %sunkaddr101, i64 64
  store <8 x double> %27, ptr %sunkaddr103, align 8
  %sunkaddr104 = mul i64 %index, 8
  %sunkaddr105 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr104
  %sunkaddr106 = getelementptr i8, ptr %sunkaddr105, i64 128
  store <8 x double> %28, ptr %sunkaddr106, align 8
  %sunkaddr107 = mul i64 %index, 8
  %sunkaddr108 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr107
  %sunkaddr109 = getelementptr i8, ptr %sunkaddr108, i64 192
  store <8 x double> %29, ptr %sunkaddr109, align 8
  %index.next = add nuw nsw i64 %index, 32
  %30 = icmp eq i64 %n.vec, %index.next
  br i1 %30, label %middle.block, label %vector.body, !llvm.loop !91

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B202, label %vec.epilog.iter.check

vec.epilog.iter.check:                            ; preds = %middle.block
  %31 = and i64 %arg.y.2, 28
  %min.epilog.iters.check = icmp eq i64 %31, 0
  br i1 %min.epilog.iters.check, label %B50.endif.preheader, label %vec.epilog.ph, !prof !9

vec.epilog.ph:                                    ; preds = %vec.epilog.iter.check, %vector.main.loop.iter.check
  %vec.epilog.resume.val = phi i64 [ %n.vec, %vec.epilog.iter.check ], [ 0, %vector.main.loop.iter.check ]
  %const_mat85 = add i64 %const84, 28
  %n.vec13 = and i64 %arg.y.2, %const_mat85
  %broadcast.splatinsert14 = insertelement <4 x double> poison, double %.546, i64 0
  %broadcast.splat15 = shufflevector <4 x double> %broadcast.splatinsert14, <4 x double> poison, <4 x i32> zeroinitializer
  br label %vec.epilog.vector.body

vec.epilog.vector.body:                           ; preds = %vec.epilog.vector.body, %vec.epilog.ph
  %index16 = phi i64 [ %vec.epilog.resume.val, %vec.epilog.ph ], [ %index.next18, %vec.epilog.vector.body ]
  %32 = shl i64 %index16, 3
  %scevgep61 = getelementptr i8, ptr %arg.y.4, i64 %32
  %wide.load17 = load <4 x double>, ptr %scevgep61, align 8
  %33 = fadd <4 x double> %broadcast.splat15, %wide.load17
  %scevgep60 = getelementptr i8, ptr %arg.ytmp.4, i64 %32
  store <4 x double> %33, ptr %scevgep60, align 8
  %index.next18 = add nuw i64 %index16, 4
  %34 = icmp eq i64 %n.vec13, %index.next18
  br i1 %34, label %vec.epilog.middle.block, label %vec.epilog.vector.body, !llvm.loop !92

vec.epilog.middle.block:                          ; preds = %vec.epilog.vector.body
  %cmp.n19 = icmp eq i64 %arg.y.2, %n.vec13
  br i1 %cmp.n19, label %B202, label %B50.endif.preheader

B50.endif.preheader:                              ; preds = %vec.epilog.middle.block, %vec.epilog.iter.check, %iter.check
  %.171254260.ph = phi i64 [ 0, %iter.check ], [ %n.vec, %vec.epilog.iter.check ], [ %n.vec13, %vec.epilog.middle.block ]
  %35 = sub nsw i64 %arg.y.2, %.171254260.ph
  %xtraiter23 = and i64 %35, 7
  %lcmp.mod24.not = icmp eq i64 %xtraiter23, 0
  br i1 %lcmp.mod24.not, label %B50.endif.prol.loopexit, label %B50.endif.prol.preheader

B50.endif.prol.preheader:                         ; preds = %B50.endif.preheader
  br label %B50.endif.prol

B50.endif.prol:                                   ; preds = %B50.endif.prol.preheader, %B50.endif.prol
  %lsr.iv = phi i64 [ %lsr.iv.next, %B50.endif.prol ], [ %xtraiter23, %B50.endif.prol.preheader ]
  %.171254260.prol = phi i64 [ %.178.prol, %B50.endif.prol ], [ %.171254260.ph, %B50.endif.prol.preheader ]
  %.178.prol = add nuw i64 %.171254260.prol, 1
  %36 = shl i64 %.171254260.prol, 3
  %scevgep59 = getelementptr i8, ptr %arg.y.4, i64 %36
  %.543.prol = load double, ptr %scevgep59, align 8
  %.549.prol = fadd double %.546, %.543.prol
  %scevgep58 = getelementptr i8, ptr %arg.ytmp.4, i64 %36
  store double %.549.prol, ptr %scevgep58, align 8
  %lsr.iv.next = add nsw i64 %lsr.iv, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next, 0
  br i1 %prol.iter.cmp.not, label %B50.endif.prol.loopexit, label %B50.endif.prol, !llvm.loop !93

B50.endif.prol.loopexit:                          ; preds = %B50.endif.prol, %B50.endif.preheader
  %.171254260.unr = phi i64 [ %.171254260.ph, %B50.endif.preheader ], [ %.178.prol, %B50.endif.prol ]
  %37 = sub nsw i64 %.171254260.ph, %arg.y.2
  %38 = icmp ugt i64 %37, -8
  br i1 %38, label %B202, label %B50.endif.preheader11

B50.endif.preheader11:                            ; preds = %B50.endif.prol.loopexit
  br label %B50.endif

B202:                                             ; preds = %B86.B166_crit_edge.us, %B50.endif, %B50.endif.prol.loopexit, %vec.epilog.middle.block, %middle.block, %B0.endif
  %.614 = icmp slt i64 %arg.s, 0
  %.615 = select i1 %.614, i64 %arg.K.5.0, i64 0
  %.616 = add i64 %.615, %arg.s
  %.633 = mul i64 %.616, %arg.K.5.1
  %.635 = getelementptr double, ptr %arg.K.4, i64 %.633
  %.663.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.K.0, 0
  %.663.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.0.insert, ptr %arg.K.1, 1
  %.663.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.1.insert, i64 %arg.K.5.1, 2
  %.663.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.2.insert, i64 %arg.K.3, 3
  %.663.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.3.insert, ptr %.635, 4
  %.663.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.4.insert, i64 %arg.K.5.1, 5, 0
  %.663.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.5.0.insert, i64 %arg.K.6.1, 6, 0
  %.676.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.ytmp.0, 0
  %.676.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.0.insert, ptr %arg.ytmp.1, 1
  %.676.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.1.insert, i64 %arg.ytmp.2, 2
  %.676.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.2.insert, i64 %arg.ytmp.3, 3
  %.676.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.3.insert, ptr %arg.ytmp.4, 4
  %.676.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.4.insert, i64 %arg.ytmp.5.0, 5, 0
  %.676.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.5.0.insert, i64 %arg.ytmp.6.0, 6, 0
  %.677.fca.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } poison, ptr %arg.par.0, 0
  %.677.fca.1.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.0.insert, ptr %arg.par.1, 1
  %.677.fca.2.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.1.insert, i64 %arg.par.2, 2
  %.677.fca.3.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.2.insert, i64 %arg.par.3, 3
  %.677.fca.4.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.3.insert, ptr %arg.par.4, 4
  %.677.fca.5.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.4.insert, i64 %arg.par.5.0, 5, 0
  %.677.fca.6.0.insert = insertvalue { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.5.0.insert, i64 %arg.par.6.0, 6, 0
  %.687 = icmp eq ptr %arg.f.2, null
  br i1 %.687, label %B202.if, label %B202.else, !prof !0

B50.endif:                                        ; preds = %B50.endif.preheader11, %B50.endif
  %.171254260 = phi i64 [ %.178.7, %B50.endif ], [ %.171254260.unr, %B50.endif.preheader11 ]
  %sunkaddr110 = mul i64 %.171254260, 8
  %sunkaddr111 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr110
  %.543 = load double, ptr %sunkaddr111, align 8
  %.549 = fadd double %.546, %.543
  %sunkaddr112 = mul i64 %.171254260, 8
  %sunkaddr114 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr112
  store double %.549, ptr %sunkaddr114, align 8
  %sunkaddr115 = mul i64 %.171254260, 8
  %sunkaddr116 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr115
  %sunkaddr117 = getelementptr i8, ptr %sunkaddr116, i64 8
  %.543.1 = load double, ptr %sunkaddr117, align 8
  %.549.1 = fadd double %.546, %.543.1
  %sunkaddr118 = mul i64 %.171254260, 8
  %sunkaddr119 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr118
  %sunkaddr120 = getelementptr i8, ptr %sunkaddr119, i64 8
  store double %.549.1, ptr %sunkaddr120, align 8
  %sunkaddr121 = mul i64 %.171254260, 8
  %sunkaddr122 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr121
  %sunkaddr123 = getelementptr i8, ptr %sunkaddr122, i64 16
  %.543.2 = load double, ptr %sunkaddr123, align 8
  %.549.2 = fadd double %.546, %.543.2
  %sunkaddr124 = mul i64 %.171254260, 8
  %sunkaddr125 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr124
  %sunkaddr126 = getelementptr i8, ptr %sunkaddr125, i64 16
  store double %.549.2, ptr %sunkaddr126, align 8
  %sunkaddr127 = mul i64 %.171254260, 8
  %sunkaddr128 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr127
  %sunkaddr129 = getelementptr i8, ptr %sunkaddr128, i64 24
  %.543.3 = load double, ptr %sunkaddr129, align 8
  %.549.3 = fadd double %.546, %.543.3
  %sunkaddr130 = mul i64 %.171254260, 8
  %sunkaddr131 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr130
  %sunkaddr132 = getelementptr i8, ptr %sunkaddr131, i64 24
  store double %.549.3, ptr %sunkaddr132, align 8
  %sunkaddr133 = mul i64 %.171254260, 8
  %sunkaddr134 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr133
  %sunkaddr135 = getelementptr i8, ptr %sunkaddr134, i64 32
  %.543.4 = load double, ptr %sunkaddr135, align 8
  %.549.4 = fadd double %.546, %.543.4
  %sunkaddr136 = mul i64 %.171254260, 8
  %sunkaddr137 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr136
  %sunkaddr138 = getelementptr i8, ptr %sunkaddr137, i64 32
  store double %.549.4, ptr %sunkaddr138, align 8
  %sunkaddr139 = mul i64 %.171254260, 8
  %sunkaddr140 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr139
  %sunkaddr141 = getelementptr i8, ptr %sunkaddr140, i64 40
  %.543.5 = load double, ptr %sunkaddr141, align 8
  %.549.5 = fadd double %.546, %.543.5
  %sunkaddr142 = mul i64 %.171254260, 8
  %sunkaddr143 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr142
  %sunkaddr144 = getelementptr i8, ptr %sunkaddr143, i64 40
  store double %.549.5, ptr %sunkaddr144, align 8
  %sunkaddr145 = mul i64 %.171254260, 8
  %sunkaddr146 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr145
  %sunkaddr147 = getelementptr i8, ptr %sunkaddr146, i64 48
  %.543.6 = load double, ptr %sunkaddr147, align 8
  %.549.6 = fadd double %.546, %.543.6
  %sunkaddr148 = mul i64 %.171254260, 8
  %sunkaddr149 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr148
  %sunkaddr150 = getelementptr i8, ptr %sunkaddr149, i64 48
  store double %.549.6, ptr %sunkaddr150, align 8
  %.178.7 = add nuw nsw i64 %.171254260, 8
  %sunkaddr151 = mul i64 %.171254260, 8
  %sunkaddr152 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr151
  %sunkaddr153 = getelementptr i8, ptr %sunkaddr152, i64 56
  %.543.7 = load double, ptr %sunkaddr153, align 8
  %.549.7 = fadd double %.546, %.543.7
  %sunkaddr154 = mul i64 %.171254260, 8
  %sunkaddr155 = getelementptr i8, ptr %arg.ytmp.4, i64 %sunkaddr154
  %sunkaddr156 = getelementptr i8, ptr %sunkaddr155, i64 56
  store double %.549.7, ptr %sunkaddr156, align 8
  %exitcond271.not.7 = icmp eq i64 %arg.y.2, %.178.7
  br i1 %exitcond271.not.7, label %B202, label %B50.endif, !llvm.loop !94

B202.if:                                          ; preds = %B202
  %.691 = icmp eq ptr %arg.f.0, null
  br i1 %.691, label %B202.if.if, label %B202.if.endif, !prof !0

B202.else:                                        ; preds = %B202
  store double 0.000000e+00, ptr %.738, align 8
  %.748 = call i32 %arg.f.2(ptr nonnull %.738, ptr nonnull %excinfo.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.5.1, i64 %arg.K.3, ptr %.635, i64 %arg.K.5.1, i64 %arg.K.6.1)
  %.758 = load double, ptr %.738, align 8
  switch i32 %.748, label %B202.else.if.if [
    i32 -2, label %B202.endif
    i32 0, label %B202.endif
  ], !prof !4

common.ret:                                       ; preds = %B202.else.if.if, %B202.if.if.endif.if, %B202.if.if.if, %B202.endif
  %common.ret.op = phi i32 [ 0, %B202.endif ], [ 1, %B202.if.if.if ], [ 1, %B202.if.if.endif.if ], [ %.748, %B202.else.if.if ]
  ret i32 %common.ret.op

B202.endif:                                       ; preds = %B202.if.endif, %B202.else, %B202.else
  %.685.0 = phi double [ %.734, %B202.if.endif ], [ %.758, %B202.else ], [ %.758, %B202.else ]
  call void @NRT_decref(ptr %arg.ytmp.0)
  call void @NRT_decref(ptr %arg.par.0)
  call void @NRT_decref(ptr %arg.K.0)
  store double %.685.0, ptr %retptr, align 8
  br label %common.ret

B202.if.if:                                       ; preds = %B202.if
  %.693 = load ptr, ptr @_ZN08NumbaEnv6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE, align 8
  %.694 = icmp eq ptr %.693, null
  br i1 %.694, label %B202.if.if.if, label %B202.if.if.endif, !prof !0

B202.if.endif:                                    ; preds = %B202.if.if.endif.endif, %B202.if
  %fptr_of_f.0 = phi ptr [ %.724, %B202.if.if.endif.endif ], [ %arg.f.0, %B202.if ]
  %.734 = call double %fptr_of_f.0({ ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.676.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.677.fca.6.0.insert, { ptr, ptr, i64, i64, ptr, [1 x i64], [1 x i64] } %.663.fca.6.0.insert)
  br label %B202.endif

B202.if.if.if:                                    ; preds = %B202.if.if
  store ptr @.const.picklebuf.4004c2ff75c85dd682fe6bf6d34405e3be8f361c, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B202.if.if.endif:                                 ; preds = %B202.if.if
  call void @numba_gil_ensure(ptr nonnull %.703)
  %.706 = call ptr @PyImport_ImportModule(ptr nonnull @.const.numba.experimental.function_type.13)
  %.707 = call ptr @PyObject_GetAttrString(ptr %.706, ptr nonnull @.const._get_wrapper_address.14)
  call void @Py_DecRef(ptr %.706)
  %.715 = call ptr @numba_unpickle(ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.15, i32 380, ptr nonnull @.const.pickledata.0d503ad516df3b4e9f77f951fb0ca35436fea2f4.sha1.16)
  %.716 = call ptr (ptr, ...) @PyObject_CallFunctionObjArgs(ptr %.707, ptr %arg.f.1, ptr %.715, ptr null)
  %.717 = icmp eq ptr %.716, null
  br i1 %.717, label %B202.if.if.endif.if, label %B202.if.if.endif.endif, !prof !0

B202.if.if.endif.if:                              ; preds = %B202.if.if.endif
  store ptr @.const.picklebuf.51fac48a62be4cbf2f5a4837d75a1cd17a138c25, ptr %excinfo, align 8, !numba_exception_output !18
  br label %common.ret

B202.if.if.endif.endif:                           ; preds = %B202.if.if.endif
  %.724 = call ptr @PyLong_AsVoidPtr(ptr nonnull %.716)
  call void @Py_DecRef(ptr nonnull %.716)
  call void @numba_gil_release(ptr nonnull %.703)
  br label %B202.if.endif

B202.else.if.if:                                  ; preds = %B202.else
  %.756 = icmp sgt i32 %.748, 0
  %.749 = load ptr, ptr %excinfo.1, align 8
  %.757 = select i1 %.756, ptr %.749, ptr undef
  store ptr %.757, ptr %excinfo, align 8
  br label %common.ret
}

define linkonce_odr range(i32 -1, -2) i32 @_ZN6charts7solvers2rk12dop853_denseB3v92B40c8tJTIeFIjxB2IKSgI4CrvSCKg1MMfAwK4LIaQIAE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias writeonly captures(none) %excinfo, ptr readonly captures(address_is_null) %arg.f.0, ptr %arg.f.1, ptr readonly captures(address_is_null) %arg.f.2, ptr %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.ynew.0, ptr readnone captures(none) %arg.ynew.1, i64 %arg.ynew.2, i64 %arg.ynew.3, ptr readonly captures(none) %arg.ynew.4, i64 %arg.ynew.5.0, i64 %arg.ynew.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0, ptr %arg.F.0, ptr readnone captures(none) %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr writeonly captures(none) %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1) local_unnamed_addr {
B0.endif.endif:
  %.245 = alloca double, align 8
  %excinfo.1 = alloca ptr, align 8
  store ptr null, ptr %excinfo.1, align 8
  tail call void @NRT_incref(ptr %arg.y.0)
  tail call void @NRT_incref(ptr %arg.ynew.0)
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.K.0)
  tail call void @NRT_incref(ptr %arg.ytmp.0)
  tail call void @NRT_incref(ptr %arg.F.0)
  %.259 = call i32 @_ZN6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.245, ptr nonnull %excinfo.1, ptr %arg.f.0, ptr %arg.f.1, ptr %arg.f.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, i64 13, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0)
  %cond = icmp eq i32 %.259, 0
  br i1 %cond, label %B78.endif, label %B78.if.if, !prof !1

B230:                                             ; preds = %B230.preheader479, %B230
  %lsr.iv559 = phi i64 [ 0, %B230.preheader479 ], [ %lsr.iv.next560, %B230 ]
  %0 = shl i64 %lsr.iv559, 3
  %scevgep613 = getelementptr i8, ptr %scevgep609, i64 %0
  %scevgep614 = getelementptr i8, ptr %scevgep613, i64 -24
  %.664 = load double, ptr %scevgep614, align 8
  %scevgep605 = getelementptr i8, ptr %scevgep601, i64 %0
  %scevgep606 = getelementptr i8, ptr %scevgep605, i64 -24
  %.694 = load double, ptr %scevgep606, align 8
  %.695 = fsub double %.664, %.694
  %1 = shl i64 %lsr.iv559, 3
  %scevgep66 = getelementptr i8, ptr %scevgep65, i64 %1
  %scevgep71 = getelementptr i8, ptr %scevgep66, i64 -24
  store double %.695, ptr %scevgep71, align 8
  %2 = shl i64 %lsr.iv559, 3
  %scevgep59 = getelementptr i8, ptr %scevgep585, i64 %2
  %scevgep64 = getelementptr i8, ptr %scevgep59, i64 -24
  %.779 = load double, ptr %scevgep64, align 8
  %.781 = fmul double %arg.h, %.779
  %.782 = fsub double %.781, %.695
  %3 = shl i64 %lsr.iv559, 3
  %scevgep53 = getelementptr i8, ptr %scevgep577, i64 %3
  %scevgep58 = getelementptr i8, ptr %scevgep53, i64 -24
  store double %.782, ptr %scevgep58, align 8
  %.837 = fmul double %.695, 2.000000e+00
  %4 = shl i64 %lsr.iv559, 3
  %scevgep47 = getelementptr i8, ptr %scevgep569, i64 %4
  %scevgep52 = getelementptr i8, ptr %scevgep47, i64 -24
  %.867 = load double, ptr %scevgep52, align 8
  %.897 = load double, ptr %scevgep64, align 8
  %.898 = fadd double %.867, %.897
  %.900 = fmul double %arg.h, %.898
  %.901 = fsub double %.837, %.900
  %5 = shl i64 %lsr.iv559, 3
  %scevgep41 = getelementptr i8, ptr %scevgep561, i64 %5
  %scevgep46 = getelementptr i8, ptr %scevgep41, i64 -24
  store double %.901, ptr %scevgep46, align 8
  %scevgep78 = getelementptr i8, ptr %scevgep609, i64 %5
  %scevgep79 = getelementptr i8, ptr %scevgep78, i64 -16
  %.664.1 = load double, ptr %scevgep79, align 8
  %6 = shl i64 %lsr.iv559, 3
  %scevgep74 = getelementptr i8, ptr %scevgep601, i64 %6
  %scevgep75 = getelementptr i8, ptr %scevgep74, i64 -16
  %.694.1 = load double, ptr %scevgep75, align 8
  %.695.1 = fsub double %.664.1, %.694.1
  %7 = shl i64 %lsr.iv559, 3
  %scevgep69 = getelementptr i8, ptr %scevgep65, i64 %7
  %scevgep70 = getelementptr i8, ptr %scevgep69, i64 -16
  store double %.695.1, ptr %scevgep70, align 8
  %8 = shl i64 %lsr.iv559, 3
  %scevgep62 = getelementptr i8, ptr %scevgep585, i64 %8
  %scevgep63 = getelementptr i8, ptr %scevgep62, i64 -16
  %.779.1 = load double, ptr %scevgep63, align 8
  %.781.1 = fmul double %arg.h, %.779.1
  %.782.1 = fsub double %.781.1, %.695.1
  %9 = shl i64 %lsr.iv559, 3
  %scevgep56 = getelementptr i8, ptr %scevgep577, i64 %9
  %scevgep57 = getelementptr i8, ptr %scevgep56, i64 -16
  store double %.782.1, ptr %scevgep57, align 8
  %.837.1 = fmul double %.695.1, 2.000000e+00
  %10 = shl i64 %lsr.iv559, 3
  %scevgep50 = getelementptr i8, ptr %scevgep569, i64 %10
  %scevgep51 = getelementptr i8, ptr %scevgep50, i64 -16
  %.867.1 = load double, ptr %scevgep51, align 8
  %.897.1 = load double, ptr %scevgep63, align 8
  %.898.1 = fadd double %.867.1, %.897.1
  %.900.1 = fmul double %arg.h, %.898.1
  %.901.1 = fsub double %.837.1, %.900.1
  %11 = shl i64 %lsr.iv559, 3
  %scevgep44 = getelementptr i8, ptr %scevgep561, i64 %11
  %scevgep45 = getelementptr i8, ptr %scevgep44, i64 -16
  store double %.901.1, ptr %scevgep45, align 8
  %scevgep76 = getelementptr i8, ptr %scevgep609, i64 %11
  %scevgep77 = getelementptr i8, ptr %scevgep76, i64 -8
  %.664.2 = load double, ptr %scevgep77, align 8
  %12 = shl i64 %lsr.iv559, 3
  %scevgep72 = getelementptr i8, ptr %scevgep601, i64 %12
  %scevgep73 = getelementptr i8, ptr %scevgep72, i64 -8
  %.694.2 = load double, ptr %scevgep73, align 8
  %.695.2 = fsub double %.664.2, %.694.2
  %13 = shl i64 %lsr.iv559, 3
  %scevgep67 = getelementptr i8, ptr %scevgep65, i64 %13
  %scevgep68 = getelementptr i8, ptr %scevgep67, i64 -8
  store double %.695.2, ptr %scevgep68, align 8
  %14 = shl i64 %lsr.iv559, 3
  %scevgep60 = getelementptr i8, ptr %scevgep585, i64 %14
  %scevgep61 = getelementptr i8, ptr %scevgep60, i64 -8
  %.779.2 = load double, ptr %scevgep61, align 8
  %.781.2 = fmul double %arg.h, %.779.2
  %.782.2 = fsub double %.781.2, %.695.2
  %15 = shl i64 %lsr.iv559, 3
  %scevgep54 = getelementptr i8, ptr %scevgep577, i64 %15
  %scevgep55 = getelementptr i8, ptr %scevgep54, i64 -8
  store double %.782.2, ptr %scevgep55, align 8
  %.837.2 = fmul double %.695.2, 2.000000e+00
  %16 = shl i64 %lsr.iv559, 3
  %scevgep48 = getelementptr i8, ptr %scevgep569, i64 %16
  %scevgep49 = getelementptr i8, ptr %scevgep48, i64 -8
  %.867.2 = load double, ptr %scevgep49, align 8
  %.897.2 = load double, ptr %scevgep61, align 8
  %.898.2 = fadd double %.867.2, %.897.2
  %.900.2 = fmul double %arg.h, %.898.2
  %.901.2 = fsub double %.837.2, %.900.2
  %17 = shl i64 %lsr.iv559, 3
  %scevgep42 = getelementptr i8, ptr %scevgep561, i64 %17
  %scevgep43 = getelementptr i8, ptr %scevgep42, i64 -8
  store double %.901.2, ptr %scevgep43, align 8
  %.664.3 = load double, ptr %scevgep613, align 8
  %.694.3 = load double, ptr %scevgep605, align 8
  %.695.3 = fsub double %.664.3, %.694.3
  store double %.695.3, ptr %scevgep66, align 8
  %.779.3 = load double, ptr %scevgep59, align 8
  %.781.3 = fmul double %arg.h, %.779.3
  %.782.3 = fsub double %.781.3, %.695.3
  store double %.782.3, ptr %scevgep53, align 8
  %.837.3 = fmul double %.695.3, 2.000000e+00
  %.867.3 = load double, ptr %scevgep47, align 8
  %.897.3 = load double, ptr %scevgep59, align 8
  %.898.3 = fadd double %.867.3, %.897.3
  %.900.3 = fmul double %arg.h, %.898.3
  %.901.3 = fsub double %.837.3, %.900.3
  store double %.901.3, ptr %scevgep41, align 8
  %lsr.iv.next560 = add i64 %lsr.iv559, 4
  %exitcond.not.3 = icmp eq i64 %52, %lsr.iv.next560
  br i1 %exitcond.not.3, label %B278.endif, label %B230, !llvm.loop !95

common.ret:                                       ; preds = %B78.if.if, %B13410157
  %common.ret.op = phi i32 [ 0, %B13410157 ], [ %.259.lcssa, %B78.if.if ]
  ret i32 %common.ret.op

B13410157:                                        ; preds = %B326.endif.endif.us, %middle.block475, %B278.endif
  tail call void @NRT_decref(ptr %arg.K.0)
  tail call void @NRT_decref(ptr %arg.F.0)
  store ptr null, ptr %retptr, align 8
  br label %common.ret

B78.endif:                                        ; preds = %B0.endif.endif
  %.259.1 = call i32 @_ZN6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.245, ptr nonnull %excinfo.1, ptr %arg.f.0, ptr %arg.f.1, ptr %arg.f.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, i64 14, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0)
  %cond1 = icmp eq i32 %.259.1, 0
  br i1 %cond1, label %B78.endif.1, label %B78.if.if, !prof !1

B78.endif.1:                                      ; preds = %B78.endif
  %.259.2 = call i32 @_ZN6charts7solvers2rk6_stageB3v90B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE142FunctionType_5bfloat64_28array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_2c_20array_28float64_2c_201d_2c_20C_29_29_5d5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedEx5ArrayIdLi1E1C7mutable7alignedE(ptr nonnull %.245, ptr nonnull %excinfo.1, ptr %arg.f.0, ptr %arg.f.1, ptr %arg.f.2, ptr %arg.y.0, ptr %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.h, ptr %arg.par.0, ptr %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.K.0, ptr %arg.K.1, i64 %arg.K.2, i64 %arg.K.3, ptr %arg.K.4, i64 %arg.K.5.0, i64 %arg.K.5.1, i64 %arg.K.6.0, i64 %arg.K.6.1, i64 15, ptr %arg.ytmp.0, ptr %arg.ytmp.1, i64 %arg.ytmp.2, i64 %arg.ytmp.3, ptr %arg.ytmp.4, i64 %arg.ytmp.5.0, i64 %arg.ytmp.6.0)
  %cond2 = icmp eq i32 %.259.2, 0
  br i1 %cond2, label %B78.endif.2, label %B78.if.if, !prof !1

B78.endif.2:                                      ; preds = %B78.endif.1
  tail call void @NRT_incref(ptr %arg.K.0)
  %.407.idx = mul i64 %arg.K.5.1, 96
  %.407 = getelementptr i8, ptr %arg.K.4, i64 %.407.idx
  tail call void @NRT_incref(ptr %arg.K.0)
  tail call void @NRT_incref(ptr %arg.F.0)
  %.555 = icmp sgt i64 %arg.y.2, 0
  tail call void @NRT_decref(ptr %arg.ytmp.0)
  tail call void @NRT_decref(ptr %arg.par.0)
  br i1 %.555, label %B230.lr.ph, label %B278.endif

B78.if.if:                                        ; preds = %B78.endif.1, %B78.endif, %B0.endif.endif
  %.259.lcssa = phi i32 [ %.259, %B0.endif.endif ], [ %.259.1, %B78.endif ], [ %.259.2, %B78.endif.1 ]
  %.267 = icmp sgt i32 %.259.lcssa, 0
  %.260 = load ptr, ptr %excinfo.1, align 8
  %.268 = select i1 %.267, ptr %.260, ptr undef
  store ptr %.268, ptr %excinfo, align 8
  br label %common.ret

B230.lr.ph:                                       ; preds = %B78.endif.2
  %18 = getelementptr double, ptr %arg.F.4, i64 %arg.F.5.1
  %.idx600 = shl i64 %arg.F.5.1, 4
  %19 = getelementptr i8, ptr %arg.F.4, i64 %.idx600
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 40
  br i1 %min.iters.check, label %B230.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %B230.lr.ph
  %20 = shl i64 %arg.y.2, 3
  %scevgep = getelementptr i8, ptr %arg.F.4, i64 %20
  %21 = add i64 %arg.F.5.1, %arg.y.2
  %22 = shl i64 %21, 3
  %scevgep18 = getelementptr i8, ptr %arg.F.4, i64 %22
  %scevgep19 = getelementptr i8, ptr %19, i64 %20
  %scevgep20 = getelementptr i8, ptr %arg.ynew.4, i64 %20
  %scevgep21 = getelementptr i8, ptr %arg.y.4, i64 %20
  %scevgep22 = getelementptr i8, ptr %arg.K.4, i64 %20
  %scevgep23 = getelementptr i8, ptr %.407, i64 %20
  %bound0 = icmp ult ptr %arg.F.4, %scevgep18
  %bound1 = icmp ult ptr %18, %scevgep
  %found.conflict = and i1 %bound1, %bound0
  %bound024 = icmp ult ptr %arg.F.4, %scevgep19
  %bound125 = icmp ult ptr %19, %scevgep
  %found.conflict26 = and i1 %bound125, %bound024
  %conflict.rdx = or i1 %found.conflict, %found.conflict26
  %bound027 = icmp ult ptr %arg.F.4, %scevgep20
  %bound128 = icmp ult ptr %arg.ynew.4, %scevgep
  %found.conflict29 = and i1 %bound027, %bound128
  %conflict.rdx30 = or i1 %found.conflict29, %conflict.rdx
  %bound031 = icmp ult ptr %arg.F.4, %scevgep21
  %bound132 = icmp ult ptr %arg.y.4, %scevgep
  %found.conflict33 = and i1 %bound031, %bound132
  %conflict.rdx34 = or i1 %found.conflict33, %conflict.rdx30
  %bound035 = icmp ult ptr %arg.F.4, %scevgep22
  %bound136 = icmp ult ptr %arg.K.4, %scevgep
  %found.conflict37 = and i1 %bound035, %bound136
  %conflict.rdx38 = or i1 %found.conflict37, %conflict.rdx34
  %bound039 = icmp ult ptr %arg.F.4, %scevgep23
  %bound140 = icmp ult ptr %.407, %scevgep
  %found.conflict41 = and i1 %bound039, %bound140
  %conflict.rdx42 = or i1 %found.conflict41, %conflict.rdx38
  %bound043 = icmp ult ptr %18, %scevgep19
  %bound144 = icmp ult ptr %19, %scevgep18
  %found.conflict45 = and i1 %bound043, %bound144
  %conflict.rdx46 = or i1 %found.conflict45, %conflict.rdx42
  %bound047 = icmp ult ptr %18, %scevgep20
  %bound148 = icmp ult ptr %arg.ynew.4, %scevgep18
  %found.conflict49 = and i1 %bound047, %bound148
  %conflict.rdx50 = or i1 %found.conflict49, %conflict.rdx46
  %bound051 = icmp ult ptr %18, %scevgep21
  %bound152 = icmp ult ptr %arg.y.4, %scevgep18
  %found.conflict53 = and i1 %bound051, %bound152
  %conflict.rdx54 = or i1 %found.conflict53, %conflict.rdx50
  %bound055 = icmp ult ptr %18, %scevgep22
  %bound156 = icmp ult ptr %arg.K.4, %scevgep18
  %found.conflict57 = and i1 %bound055, %bound156
  %conflict.rdx58 = or i1 %found.conflict57, %conflict.rdx54
  %bound059 = icmp ult ptr %18, %scevgep23
  %bound160 = icmp ult ptr %.407, %scevgep18
  %found.conflict61 = and i1 %bound059, %bound160
  %conflict.rdx62 = or i1 %found.conflict61, %conflict.rdx58
  %bound063 = icmp ult ptr %19, %scevgep20
  %bound164 = icmp ult ptr %arg.ynew.4, %scevgep19
  %found.conflict65 = and i1 %bound063, %bound164
  %conflict.rdx66 = or i1 %found.conflict65, %conflict.rdx62
  %bound067 = icmp ult ptr %19, %scevgep21
  %bound168 = icmp ult ptr %arg.y.4, %scevgep19
  %found.conflict69 = and i1 %bound067, %bound168
  %conflict.rdx70 = or i1 %found.conflict69, %conflict.rdx66
  %bound071 = icmp ult ptr %19, %scevgep22
  %bound172 = icmp ult ptr %arg.K.4, %scevgep19
  %found.conflict73 = and i1 %bound071, %bound172
  %conflict.rdx74 = or i1 %found.conflict73, %conflict.rdx70
  %bound075 = icmp ult ptr %19, %scevgep23
  %bound176 = icmp ult ptr %.407, %scevgep19
  %found.conflict77 = and i1 %bound075, %bound176
  %conflict.rdx78 = or i1 %found.conflict77, %conflict.rdx74
  br i1 %conflict.rdx78, label %B230.preheader, label %vector.ph

vector.ph:                                        ; preds = %vector.memcheck
  %const132 = bitcast i64 9223372036854775800 to i64
  %n.vec = and i64 %arg.y.2, %const132
  %broadcast.splatinsert = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %23 = shl i64 %index, 3
  %scevgep637 = getelementptr i8, ptr %arg.ynew.4, i64 %23
  %wide.load = load <8 x double>, ptr %scevgep637, align 8, !alias.scope !96
  %scevgep636 = getelementptr i8, ptr %arg.y.4, i64 %23
  %wide.load79 = load <8 x double>, ptr %scevgep636, align 8, !alias.scope !99
  %24 = fsub <8 x double> %wide.load, %wide.load79
  %25 = shl i64 %index, 3
  %scevgep131 = getelementptr i8, ptr %arg.F.4, i64 %25
  store <8 x double> %24, ptr %scevgep131, align 8, !alias.scope !101, !noalias !103
  %26 = shl i64 %index, 3
  %scevgep130 = getelementptr i8, ptr %arg.K.4, i64 %26
  %wide.load80 = load <8 x double>, ptr %scevgep130, align 8, !alias.scope !108
  %27 = fmul <8 x double> %broadcast.splat, %wide.load80
  %28 = fsub <8 x double> %27, %24
  %29 = shl i64 %index, 3
  %scevgep129 = getelementptr i8, ptr %18, i64 %29
  store <8 x double> %28, ptr %scevgep129, align 8, !alias.scope !109, !noalias !110
  %30 = fmul <8 x double> %24, splat (double 2.000000e+00)
  %31 = shl i64 %index, 3
  %scevgep128 = getelementptr i8, ptr %.407, i64 %31
  %wide.load81 = load <8 x double>, ptr %scevgep128, align 8, !alias.scope !111
  %32 = fadd <8 x double> %wide.load80, %wide.load81
  %33 = fmul <8 x double> %broadcast.splat, %32
  %34 = fsub <8 x double> %30, %33
  %35 = shl i64 %index, 3
  %scevgep127 = getelementptr i8, ptr %19, i64 %35
  store <8 x double> %34, ptr %scevgep127, align 8, !alias.scope !112, !noalias !113
  %index.next = add nuw nsw i64 %index, 8
  %36 = icmp eq i64 %n.vec, %index.next
  br i1 %36, label %middle.block, label %vector.body, !llvm.loop !114

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B278.endif, label %B230.preheader

B230.preheader:                                   ; preds = %middle.block, %vector.memcheck, %B230.lr.ph
  %.603607609.ph = phi i64 [ 0, %vector.memcheck ], [ 0, %B230.lr.ph ], [ %n.vec, %middle.block ]
  %xtraiter = and i64 %arg.y.2, 3
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B230.prol.loopexit, label %B230.prol.preheader

B230.prol.preheader:                              ; preds = %B230.preheader
  %37 = shl i64 %.603607609.ph, 3
  %scevgep617 = getelementptr i8, ptr %19, i64 %37
  %scevgep619 = getelementptr i8, ptr %.407, i64 %37
  %38 = add i64 %.603607609.ph, %arg.F.5.1
  %39 = shl i64 %38, 3
  %scevgep621 = getelementptr i8, ptr %arg.F.4, i64 %39
  %scevgep623 = getelementptr i8, ptr %arg.K.4, i64 %37
  %scevgep625 = getelementptr i8, ptr %arg.F.4, i64 %37
  %scevgep627 = getelementptr i8, ptr %arg.y.4, i64 %37
  %scevgep629 = getelementptr i8, ptr %arg.ynew.4, i64 %37
  %40 = shl nuw nsw i64 %xtraiter, 3
  br label %B230.prol

B230.prol:                                        ; preds = %B230.prol, %B230.prol.preheader
  %lsr.iv80 = phi i64 [ %lsr.iv.next81, %B230.prol ], [ 0, %B230.prol.preheader ]
  %scevgep126 = getelementptr i8, ptr %scevgep629, i64 %lsr.iv80
  %.664.prol = load double, ptr %scevgep126, align 8
  %scevgep125 = getelementptr i8, ptr %scevgep627, i64 %lsr.iv80
  %.694.prol = load double, ptr %scevgep125, align 8
  %.695.prol = fsub double %.664.prol, %.694.prol
  %scevgep124 = getelementptr i8, ptr %scevgep625, i64 %lsr.iv80
  store double %.695.prol, ptr %scevgep124, align 8
  %scevgep123 = getelementptr i8, ptr %scevgep623, i64 %lsr.iv80
  %.779.prol = load double, ptr %scevgep123, align 8
  %.781.prol = fmul double %arg.h, %.779.prol
  %.782.prol = fsub double %.781.prol, %.695.prol
  %scevgep122 = getelementptr i8, ptr %scevgep621, i64 %lsr.iv80
  store double %.782.prol, ptr %scevgep122, align 8
  %.837.prol = fmul double %.695.prol, 2.000000e+00
  %scevgep83 = getelementptr i8, ptr %scevgep619, i64 %lsr.iv80
  %.867.prol = load double, ptr %scevgep83, align 8
  %.897.prol = load double, ptr %scevgep123, align 8
  %.898.prol = fadd double %.867.prol, %.897.prol
  %.900.prol = fmul double %arg.h, %.898.prol
  %.901.prol = fsub double %.837.prol, %.900.prol
  %scevgep82 = getelementptr i8, ptr %scevgep617, i64 %lsr.iv80
  store double %.901.prol, ptr %scevgep82, align 8
  %lsr.iv.next81 = add nuw nsw i64 %lsr.iv80, 8
  %prol.iter.cmp.not = icmp eq i64 %40, %lsr.iv.next81
  br i1 %prol.iter.cmp.not, label %B230.prol.loopexit.loopexit, label %B230.prol, !llvm.loop !115

B230.prol.loopexit.loopexit:                      ; preds = %B230.prol
  %41 = or disjoint i64 %xtraiter, %.603607609.ph
  br label %B230.prol.loopexit

B230.prol.loopexit:                               ; preds = %B230.prol.loopexit.loopexit, %B230.preheader
  %.603607609.unr = phi i64 [ %.603607609.ph, %B230.preheader ], [ %41, %B230.prol.loopexit.loopexit ]
  %42 = sub nsw i64 %.603607609.ph, %arg.y.2
  %43 = icmp ugt i64 %42, -4
  br i1 %43, label %B278.endif, label %B230.preheader479

B230.preheader479:                                ; preds = %B230.prol.loopexit
  %44 = shl i64 %.603607609.unr, 3
  %45 = getelementptr i8, ptr %19, i64 %44
  %scevgep561 = getelementptr i8, ptr %45, i64 24
  %46 = getelementptr i8, ptr %.407, i64 %44
  %scevgep569 = getelementptr i8, ptr %46, i64 24
  %47 = add i64 %.603607609.unr, %arg.F.5.1
  %48 = shl i64 %47, 3
  %49 = getelementptr i8, ptr %arg.F.4, i64 %48
  %scevgep577 = getelementptr i8, ptr %49, i64 24
  %50 = add i64 %44, 24
  %scevgep585 = getelementptr i8, ptr %arg.K.4, i64 %50
  %scevgep601 = getelementptr i8, ptr %arg.y.4, i64 %50
  %scevgep609 = getelementptr i8, ptr %arg.ynew.4, i64 %50
  %51 = add i64 %.603607609.ph, %xtraiter
  %52 = sub i64 %arg.y.2, %51
  %53 = shl i64 %.603607609.ph, 3
  %54 = shl nuw nsw i64 %xtraiter, 3
  %55 = add i64 %53, %54
  %56 = add i64 %55, 24
  %scevgep65 = getelementptr i8, ptr %arg.F.4, i64 %56
  br label %B230

B278.endif:                                       ; preds = %B230, %B230.prol.loopexit, %middle.block, %B78.endif.2
  tail call void @NRT_decref(ptr %arg.ynew.0)
  tail call void @NRT_decref(ptr %arg.y.0)
  tail call void @NRT_decref(ptr %arg.K.0)
  tail call void @NRT_decref(ptr %arg.K.0)
  tail call void @NRT_decref(ptr %arg.F.0)
  %.1072650.not = icmp slt i64 %arg.y.2, 1
  br i1 %.1072650.not, label %B13410157, label %B326.endif.endif.us.preheader

B326.endif.endif.us.preheader:                    ; preds = %B278.endif
  %gep622.us.us.2.idx = shl i64 %arg.K.5.1, 4
  %gep622.us.us.3.idx = mul i64 %arg.K.5.1, 24
  %gep622.us.us.4.idx = shl i64 %arg.K.5.1, 5
  %gep622.us.us.5.idx = mul i64 %arg.K.5.1, 40
  %gep622.us.us.6.idx = mul i64 %arg.K.5.1, 48
  %gep622.us.us.7.idx = mul i64 %arg.K.5.1, 56
  %gep622.us.us.8.idx = shl i64 %arg.K.5.1, 6
  %gep622.us.us.9.idx = mul i64 %arg.K.5.1, 72
  %gep622.us.us.10.idx = mul i64 %arg.K.5.1, 80
  %gep622.us.us.11.idx = mul i64 %arg.K.5.1, 88
  %gep622.us.us.13.idx = mul i64 %arg.K.5.1, 104
  %gep622.us.us.14.idx = mul i64 %arg.K.5.1, 112
  %gep622.us.us.15.idx = mul i64 %arg.K.5.1, 120
  %gep638.us.us.idx = mul i64 %arg.F.5.1, 24
  %gep638.us.us.1.idx = shl i64 %arg.F.5.1, 5
  %gep638.us.us.2.idx = mul i64 %arg.F.5.1, 40
  %gep638.us.us.3.idx = mul i64 %arg.F.5.1, 48
  %min.iters.check402 = icmp samesign ult i64 %arg.y.2, 16
  br i1 %min.iters.check402, label %B326.endif.endif.us.preheader478, label %vector.memcheck83

vector.memcheck83:                                ; preds = %B326.endif.endif.us.preheader
  %scevgep84 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.idx
  %57 = shl i64 %arg.y.2, 3
  %scevgep85 = getelementptr i8, ptr %scevgep84, i64 %57
  %scevgep86 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.1.idx
  %scevgep87 = getelementptr i8, ptr %scevgep86, i64 %57
  %scevgep88 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.2.idx
  %scevgep89 = getelementptr i8, ptr %scevgep88, i64 %57
  %scevgep90 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.3.idx
  %scevgep91 = getelementptr i8, ptr %scevgep90, i64 %57
  %scevgep92 = getelementptr i8, ptr %arg.K.4, i64 %57
  %58 = shl i64 %arg.K.5.1, 3
  %scevgep93 = getelementptr i8, ptr %arg.K.4, i64 %58
  %scevgep94 = getelementptr i8, ptr %scevgep93, i64 %57
  %scevgep95 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.2.idx
  %scevgep96 = getelementptr i8, ptr %scevgep95, i64 %57
  %scevgep97 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.3.idx
  %scevgep98 = getelementptr i8, ptr %scevgep97, i64 %57
  %scevgep99 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.4.idx
  %scevgep100 = getelementptr i8, ptr %scevgep99, i64 %57
  %scevgep101 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.5.idx
  %scevgep102 = getelementptr i8, ptr %scevgep101, i64 %57
  %scevgep103 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.6.idx
  %scevgep104 = getelementptr i8, ptr %scevgep103, i64 %57
  %scevgep105 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.7.idx
  %scevgep106 = getelementptr i8, ptr %scevgep105, i64 %57
  %scevgep107 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.8.idx
  %scevgep108 = getelementptr i8, ptr %scevgep107, i64 %57
  %scevgep109 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.9.idx
  %scevgep110 = getelementptr i8, ptr %scevgep109, i64 %57
  %scevgep111 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.10.idx
  %scevgep112 = getelementptr i8, ptr %scevgep111, i64 %57
  %scevgep113 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.11.idx
  %scevgep114 = getelementptr i8, ptr %scevgep113, i64 %57
  %scevgep115 = getelementptr i8, ptr %.407, i64 %57
  %scevgep116 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.13.idx
  %scevgep117 = getelementptr i8, ptr %scevgep116, i64 %57
  %scevgep118 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.14.idx
  %scevgep119 = getelementptr i8, ptr %scevgep118, i64 %57
  %scevgep120 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.15.idx
  %scevgep121 = getelementptr i8, ptr %scevgep120, i64 %57
  %bound0122 = icmp ult ptr %scevgep84, %scevgep87
  %bound1123 = icmp ult ptr %scevgep86, %scevgep85
  %found.conflict124 = and i1 %bound0122, %bound1123
  %bound0125 = icmp ult ptr %scevgep84, %scevgep89
  %bound1126 = icmp ult ptr %scevgep88, %scevgep85
  %found.conflict127 = and i1 %bound0125, %bound1126
  %conflict.rdx128 = or i1 %found.conflict124, %found.conflict127
  %bound0129 = icmp ult ptr %scevgep84, %scevgep91
  %bound1130 = icmp ult ptr %scevgep90, %scevgep85
  %found.conflict131 = and i1 %bound0129, %bound1130
  %conflict.rdx132 = or i1 %found.conflict131, %conflict.rdx128
  %bound0133 = icmp ult ptr %scevgep84, %scevgep92
  %bound1134 = icmp ult ptr %arg.K.4, %scevgep85
  %found.conflict135 = and i1 %bound0133, %bound1134
  %conflict.rdx136 = or i1 %found.conflict135, %conflict.rdx132
  %bound0137 = icmp ult ptr %scevgep84, %scevgep94
  %bound1138 = icmp ult ptr %scevgep93, %scevgep85
  %found.conflict139 = and i1 %bound0137, %bound1138
  %conflict.rdx140 = or i1 %found.conflict139, %conflict.rdx136
  %bound0141 = icmp ult ptr %scevgep84, %scevgep96
  %bound1142 = icmp ult ptr %scevgep95, %scevgep85
  %found.conflict143 = and i1 %bound0141, %bound1142
  %conflict.rdx144 = or i1 %found.conflict143, %conflict.rdx140
  %bound0145 = icmp ult ptr %scevgep84, %scevgep98
  %bound1146 = icmp ult ptr %scevgep97, %scevgep85
  %found.conflict147 = and i1 %bound0145, %bound1146
  %conflict.rdx148 = or i1 %found.conflict147, %conflict.rdx144
  %bound0149 = icmp ult ptr %scevgep84, %scevgep100
  %bound1150 = icmp ult ptr %scevgep99, %scevgep85
  %found.conflict151 = and i1 %bound0149, %bound1150
  %conflict.rdx152 = or i1 %found.conflict151, %conflict.rdx148
  %bound0153 = icmp ult ptr %scevgep84, %scevgep102
  %bound1154 = icmp ult ptr %scevgep101, %scevgep85
  %found.conflict155 = and i1 %bound0153, %bound1154
  %conflict.rdx156 = or i1 %found.conflict155, %conflict.rdx152
  %bound0157 = icmp ult ptr %scevgep84, %scevgep104
  %bound1158 = icmp ult ptr %scevgep103, %scevgep85
  %found.conflict159 = and i1 %bound0157, %bound1158
  %conflict.rdx160 = or i1 %found.conflict159, %conflict.rdx156
  %bound0161 = icmp ult ptr %scevgep84, %scevgep106
  %bound1162 = icmp ult ptr %scevgep105, %scevgep85
  %found.conflict163 = and i1 %bound0161, %bound1162
  %conflict.rdx164 = or i1 %found.conflict163, %conflict.rdx160
  %bound0165 = icmp ult ptr %scevgep84, %scevgep108
  %bound1166 = icmp ult ptr %scevgep107, %scevgep85
  %found.conflict167 = and i1 %bound0165, %bound1166
  %conflict.rdx168 = or i1 %found.conflict167, %conflict.rdx164
  %bound0169 = icmp ult ptr %scevgep84, %scevgep110
  %bound1170 = icmp ult ptr %scevgep109, %scevgep85
  %found.conflict171 = and i1 %bound0169, %bound1170
  %conflict.rdx172 = or i1 %found.conflict171, %conflict.rdx168
  %bound0173 = icmp ult ptr %scevgep84, %scevgep112
  %bound1174 = icmp ult ptr %scevgep111, %scevgep85
  %found.conflict175 = and i1 %bound0173, %bound1174
  %conflict.rdx176 = or i1 %found.conflict175, %conflict.rdx172
  %bound0177 = icmp ult ptr %scevgep84, %scevgep114
  %bound1178 = icmp ult ptr %scevgep113, %scevgep85
  %found.conflict179 = and i1 %bound0177, %bound1178
  %conflict.rdx180 = or i1 %found.conflict179, %conflict.rdx176
  %bound0181 = icmp ult ptr %scevgep84, %scevgep115
  %bound1182 = icmp ult ptr %.407, %scevgep85
  %found.conflict183 = and i1 %bound0181, %bound1182
  %conflict.rdx184 = or i1 %found.conflict183, %conflict.rdx180
  %bound0185 = icmp ult ptr %scevgep84, %scevgep117
  %bound1186 = icmp ult ptr %scevgep116, %scevgep85
  %found.conflict187 = and i1 %bound0185, %bound1186
  %conflict.rdx188 = or i1 %found.conflict187, %conflict.rdx184
  %bound0189 = icmp ult ptr %scevgep84, %scevgep119
  %bound1190 = icmp ult ptr %scevgep118, %scevgep85
  %found.conflict191 = and i1 %bound0189, %bound1190
  %conflict.rdx192 = or i1 %found.conflict191, %conflict.rdx188
  %bound0193 = icmp ult ptr %scevgep84, %scevgep121
  %bound1194 = icmp ult ptr %scevgep120, %scevgep85
  %found.conflict195 = and i1 %bound0193, %bound1194
  %conflict.rdx196 = or i1 %found.conflict195, %conflict.rdx192
  %bound0197 = icmp ult ptr %scevgep86, %scevgep89
  %bound1198 = icmp ult ptr %scevgep88, %scevgep87
  %found.conflict199 = and i1 %bound0197, %bound1198
  %conflict.rdx200 = or i1 %found.conflict199, %conflict.rdx196
  %bound0201 = icmp ult ptr %scevgep86, %scevgep91
  %bound1202 = icmp ult ptr %scevgep90, %scevgep87
  %found.conflict203 = and i1 %bound0201, %bound1202
  %conflict.rdx204 = or i1 %found.conflict203, %conflict.rdx200
  %bound0205 = icmp ult ptr %scevgep86, %scevgep92
  %bound1206 = icmp ult ptr %arg.K.4, %scevgep87
  %found.conflict207 = and i1 %bound0205, %bound1206
  %conflict.rdx208 = or i1 %found.conflict207, %conflict.rdx204
  %bound0209 = icmp ult ptr %scevgep86, %scevgep94
  %bound1210 = icmp ult ptr %scevgep93, %scevgep87
  %found.conflict211 = and i1 %bound0209, %bound1210
  %conflict.rdx212 = or i1 %found.conflict211, %conflict.rdx208
  %bound0213 = icmp ult ptr %scevgep86, %scevgep96
  %bound1214 = icmp ult ptr %scevgep95, %scevgep87
  %found.conflict215 = and i1 %bound0213, %bound1214
  %conflict.rdx216 = or i1 %found.conflict215, %conflict.rdx212
  %bound0217 = icmp ult ptr %scevgep86, %scevgep98
  %bound1218 = icmp ult ptr %scevgep97, %scevgep87
  %found.conflict219 = and i1 %bound0217, %bound1218
  %conflict.rdx220 = or i1 %found.conflict219, %conflict.rdx216
  %bound0221 = icmp ult ptr %scevgep86, %scevgep100
  %bound1222 = icmp ult ptr %scevgep99, %scevgep87
  %found.conflict223 = and i1 %bound0221, %bound1222
  %conflict.rdx224 = or i1 %found.conflict223, %conflict.rdx220
  %bound0225 = icmp ult ptr %scevgep86, %scevgep102
  %bound1226 = icmp ult ptr %scevgep101, %scevgep87
  %found.conflict227 = and i1 %bound0225, %bound1226
  %conflict.rdx228 = or i1 %found.conflict227, %conflict.rdx224
  %bound0229 = icmp ult ptr %scevgep86, %scevgep104
  %bound1230 = icmp ult ptr %scevgep103, %scevgep87
  %found.conflict231 = and i1 %bound0229, %bound1230
  %conflict.rdx232 = or i1 %found.conflict231, %conflict.rdx228
  %bound0233 = icmp ult ptr %scevgep86, %scevgep106
  %bound1234 = icmp ult ptr %scevgep105, %scevgep87
  %found.conflict235 = and i1 %bound0233, %bound1234
  %conflict.rdx236 = or i1 %found.conflict235, %conflict.rdx232
  %bound0237 = icmp ult ptr %scevgep86, %scevgep108
  %bound1238 = icmp ult ptr %scevgep107, %scevgep87
  %found.conflict239 = and i1 %bound0237, %bound1238
  %conflict.rdx240 = or i1 %found.conflict239, %conflict.rdx236
  %bound0241 = icmp ult ptr %scevgep86, %scevgep110
  %bound1242 = icmp ult ptr %scevgep109, %scevgep87
  %found.conflict243 = and i1 %bound0241, %bound1242
  %conflict.rdx244 = or i1 %found.conflict243, %conflict.rdx240
  %bound0245 = icmp ult ptr %scevgep86, %scevgep112
  %bound1246 = icmp ult ptr %scevgep111, %scevgep87
  %found.conflict247 = and i1 %bound0245, %bound1246
  %conflict.rdx248 = or i1 %found.conflict247, %conflict.rdx244
  %bound0249 = icmp ult ptr %scevgep86, %scevgep114
  %bound1250 = icmp ult ptr %scevgep113, %scevgep87
  %found.conflict251 = and i1 %bound0249, %bound1250
  %conflict.rdx252 = or i1 %found.conflict251, %conflict.rdx248
  %bound0253 = icmp ult ptr %scevgep86, %scevgep115
  %bound1254 = icmp ult ptr %.407, %scevgep87
  %found.conflict255 = and i1 %bound0253, %bound1254
  %conflict.rdx256 = or i1 %found.conflict255, %conflict.rdx252
  %bound0257 = icmp ult ptr %scevgep86, %scevgep117
  %bound1258 = icmp ult ptr %scevgep116, %scevgep87
  %found.conflict259 = and i1 %bound0257, %bound1258
  %conflict.rdx260 = or i1 %found.conflict259, %conflict.rdx256
  %bound0261 = icmp ult ptr %scevgep86, %scevgep119
  %bound1262 = icmp ult ptr %scevgep118, %scevgep87
  %found.conflict263 = and i1 %bound0261, %bound1262
  %conflict.rdx264 = or i1 %found.conflict263, %conflict.rdx260
  %bound0265 = icmp ult ptr %scevgep86, %scevgep121
  %bound1266 = icmp ult ptr %scevgep120, %scevgep87
  %found.conflict267 = and i1 %bound0265, %bound1266
  %conflict.rdx268 = or i1 %found.conflict267, %conflict.rdx264
  %bound0269 = icmp ult ptr %scevgep88, %scevgep91
  %bound1270 = icmp ult ptr %scevgep90, %scevgep89
  %found.conflict271 = and i1 %bound0269, %bound1270
  %conflict.rdx272 = or i1 %found.conflict271, %conflict.rdx268
  %bound0273 = icmp ult ptr %scevgep88, %scevgep92
  %bound1274 = icmp ult ptr %arg.K.4, %scevgep89
  %found.conflict275 = and i1 %bound0273, %bound1274
  %conflict.rdx276 = or i1 %found.conflict275, %conflict.rdx272
  %bound0277 = icmp ult ptr %scevgep88, %scevgep94
  %bound1278 = icmp ult ptr %scevgep93, %scevgep89
  %found.conflict279 = and i1 %bound0277, %bound1278
  %conflict.rdx280 = or i1 %found.conflict279, %conflict.rdx276
  %bound0281 = icmp ult ptr %scevgep88, %scevgep96
  %bound1282 = icmp ult ptr %scevgep95, %scevgep89
  %found.conflict283 = and i1 %bound0281, %bound1282
  %conflict.rdx284 = or i1 %found.conflict283, %conflict.rdx280
  %bound0285 = icmp ult ptr %scevgep88, %scevgep98
  %bound1286 = icmp ult ptr %scevgep97, %scevgep89
  %found.conflict287 = and i1 %bound0285, %bound1286
  %conflict.rdx288 = or i1 %found.conflict287, %conflict.rdx284
  %bound0289 = icmp ult ptr %scevgep88, %scevgep100
  %bound1290 = icmp ult ptr %scevgep99, %scevgep89
  %found.conflict291 = and i1 %bound0289, %bound1290
  %conflict.rdx292 = or i1 %found.conflict291, %conflict.rdx288
  %bound0293 = icmp ult ptr %scevgep88, %scevgep102
  %bound1294 = icmp ult ptr %scevgep101, %scevgep89
  %found.conflict295 = and i1 %bound0293, %bound1294
  %conflict.rdx296 = or i1 %found.conflict295, %conflict.rdx292
  %bound0297 = icmp ult ptr %scevgep88, %scevgep104
  %bound1298 = icmp ult ptr %scevgep103, %scevgep89
  %found.conflict299 = and i1 %bound0297, %bound1298
  %conflict.rdx300 = or i1 %found.conflict299, %conflict.rdx296
  %bound0301 = icmp ult ptr %scevgep88, %scevgep106
  %bound1302 = icmp ult ptr %scevgep105, %scevgep89
  %found.conflict303 = and i1 %bound0301, %bound1302
  %conflict.rdx304 = or i1 %found.conflict303, %conflict.rdx300
  %bound0305 = icmp ult ptr %scevgep88, %scevgep108
  %bound1306 = icmp ult ptr %scevgep107, %scevgep89
  %found.conflict307 = and i1 %bound0305, %bound1306
  %conflict.rdx308 = or i1 %found.conflict307, %conflict.rdx304
  %bound0309 = icmp ult ptr %scevgep88, %scevgep110
  %bound1310 = icmp ult ptr %scevgep109, %scevgep89
  %found.conflict311 = and i1 %bound0309, %bound1310
  %conflict.rdx312 = or i1 %found.conflict311, %conflict.rdx308
  %bound0313 = icmp ult ptr %scevgep88, %scevgep112
  %bound1314 = icmp ult ptr %scevgep111, %scevgep89
  %found.conflict315 = and i1 %bound0313, %bound1314
  %conflict.rdx316 = or i1 %found.conflict315, %conflict.rdx312
  %bound0317 = icmp ult ptr %scevgep88, %scevgep114
  %bound1318 = icmp ult ptr %scevgep113, %scevgep89
  %found.conflict319 = and i1 %bound0317, %bound1318
  %conflict.rdx320 = or i1 %found.conflict319, %conflict.rdx316
  %bound0321 = icmp ult ptr %scevgep88, %scevgep115
  %bound1322 = icmp ult ptr %.407, %scevgep89
  %found.conflict323 = and i1 %bound0321, %bound1322
  %conflict.rdx324 = or i1 %found.conflict323, %conflict.rdx320
  %bound0325 = icmp ult ptr %scevgep88, %scevgep117
  %bound1326 = icmp ult ptr %scevgep116, %scevgep89
  %found.conflict327 = and i1 %bound0325, %bound1326
  %conflict.rdx328 = or i1 %found.conflict327, %conflict.rdx324
  %bound0329 = icmp ult ptr %scevgep88, %scevgep119
  %bound1330 = icmp ult ptr %scevgep118, %scevgep89
  %found.conflict331 = and i1 %bound0329, %bound1330
  %conflict.rdx332 = or i1 %found.conflict331, %conflict.rdx328
  %bound0333 = icmp ult ptr %scevgep88, %scevgep121
  %bound1334 = icmp ult ptr %scevgep120, %scevgep89
  %found.conflict335 = and i1 %bound0333, %bound1334
  %conflict.rdx336 = or i1 %found.conflict335, %conflict.rdx332
  %bound0337 = icmp ult ptr %scevgep90, %scevgep92
  %bound1338 = icmp ult ptr %arg.K.4, %scevgep91
  %found.conflict339 = and i1 %bound0337, %bound1338
  %conflict.rdx340 = or i1 %found.conflict339, %conflict.rdx336
  %bound0341 = icmp ult ptr %scevgep90, %scevgep94
  %bound1342 = icmp ult ptr %scevgep93, %scevgep91
  %found.conflict343 = and i1 %bound0341, %bound1342
  %conflict.rdx344 = or i1 %found.conflict343, %conflict.rdx340
  %bound0345 = icmp ult ptr %scevgep90, %scevgep96
  %bound1346 = icmp ult ptr %scevgep95, %scevgep91
  %found.conflict347 = and i1 %bound0345, %bound1346
  %conflict.rdx348 = or i1 %found.conflict347, %conflict.rdx344
  %bound0349 = icmp ult ptr %scevgep90, %scevgep98
  %bound1350 = icmp ult ptr %scevgep97, %scevgep91
  %found.conflict351 = and i1 %bound0349, %bound1350
  %conflict.rdx352 = or i1 %found.conflict351, %conflict.rdx348
  %bound0353 = icmp ult ptr %scevgep90, %scevgep100
  %bound1354 = icmp ult ptr %scevgep99, %scevgep91
  %found.conflict355 = and i1 %bound0353, %bound1354
  %conflict.rdx356 = or i1 %found.conflict355, %conflict.rdx352
  %bound0357 = icmp ult ptr %scevgep90, %scevgep102
  %bound1358 = icmp ult ptr %scevgep101, %scevgep91
  %found.conflict359 = and i1 %bound0357, %bound1358
  %conflict.rdx360 = or i1 %found.conflict359, %conflict.rdx356
  %bound0361 = icmp ult ptr %scevgep90, %scevgep104
  %bound1362 = icmp ult ptr %scevgep103, %scevgep91
  %found.conflict363 = and i1 %bound0361, %bound1362
  %conflict.rdx364 = or i1 %found.conflict363, %conflict.rdx360
  %bound0365 = icmp ult ptr %scevgep90, %scevgep106
  %bound1366 = icmp ult ptr %scevgep105, %scevgep91
  %found.conflict367 = and i1 %bound0365, %bound1366
  %conflict.rdx368 = or i1 %found.conflict367, %conflict.rdx364
  %bound0369 = icmp ult ptr %scevgep90, %scevgep108
  %bound1370 = icmp ult ptr %scevgep107, %scevgep91
  %found.conflict371 = and i1 %bound0369, %bound1370
  %conflict.rdx372 = or i1 %found.conflict371, %conflict.rdx368
  %bound0373 = icmp ult ptr %scevgep90, %scevgep110
  %bound1374 = icmp ult ptr %scevgep109, %scevgep91
  %found.conflict375 = and i1 %bound0373, %bound1374
  %conflict.rdx376 = or i1 %found.conflict375, %conflict.rdx372
  %bound0377 = icmp ult ptr %scevgep90, %scevgep112
  %bound1378 = icmp ult ptr %scevgep111, %scevgep91
  %found.conflict379 = and i1 %bound0377, %bound1378
  %conflict.rdx380 = or i1 %found.conflict379, %conflict.rdx376
  %bound0381 = icmp ult ptr %scevgep90, %scevgep114
  %bound1382 = icmp ult ptr %scevgep113, %scevgep91
  %found.conflict383 = and i1 %bound0381, %bound1382
  %conflict.rdx384 = or i1 %found.conflict383, %conflict.rdx380
  %bound0385 = icmp ult ptr %scevgep90, %scevgep115
  %bound1386 = icmp ult ptr %.407, %scevgep91
  %found.conflict387 = and i1 %bound0385, %bound1386
  %conflict.rdx388 = or i1 %found.conflict387, %conflict.rdx384
  %bound0389 = icmp ult ptr %scevgep90, %scevgep117
  %bound1390 = icmp ult ptr %scevgep116, %scevgep91
  %found.conflict391 = and i1 %bound0389, %bound1390
  %conflict.rdx392 = or i1 %found.conflict391, %conflict.rdx388
  %bound0393 = icmp ult ptr %scevgep90, %scevgep119
  %bound1394 = icmp ult ptr %scevgep118, %scevgep91
  %found.conflict395 = and i1 %bound0393, %bound1394
  %conflict.rdx396 = or i1 %found.conflict395, %conflict.rdx392
  %bound0397 = icmp ult ptr %scevgep90, %scevgep121
  %bound1398 = icmp ult ptr %scevgep120, %scevgep91
  %found.conflict399 = and i1 %bound0397, %bound1398
  %conflict.rdx400 = or i1 %found.conflict399, %conflict.rdx396
  br i1 %conflict.rdx400, label %B326.endif.endif.us.preheader478, label %vector.ph403

vector.ph403:                                     ; preds = %vector.memcheck83
  %const = bitcast i64 9223372036854775800 to i64
  %n.vec405 = and i64 %arg.y.2, %const
  %broadcast.splatinsert406 = insertelement <8 x double> poison, double %arg.h, i64 0
  %broadcast.splat407 = shufflevector <8 x double> %broadcast.splatinsert406, <8 x double> poison, <8 x i32> zeroinitializer
  br label %vector.body408

vector.body408:                                   ; preds = %vector.body408, %vector.ph403
  %index409 = phi i64 [ 0, %vector.ph403 ], [ %index.next474, %vector.body408 ]
  %59 = shl i64 %index409, 3
  %scevgep520 = getelementptr i8, ptr %arg.K.4, i64 %59
  %wide.load410 = load <8 x double>, ptr %scevgep520, align 8, !alias.scope !116
  %60 = fmul <8 x double> %wide.load410, splat (double 0x4020DB9DCC37C81B)
  %61 = fsub <8 x double> zeroinitializer, %60
  %scevgep26 = getelementptr i8, ptr %scevgep520, i64 %58
  %wide.load411 = load <8 x double>, ptr %scevgep26, align 8, !alias.scope !119
  %62 = fmul <8 x double> %wide.load411, zeroinitializer
  %63 = fadd <8 x double> %61, %62
  %scevgep27 = getelementptr i8, ptr %scevgep26, i64 %58
  %wide.load412 = load <8 x double>, ptr %scevgep27, align 8, !alias.scope !121
  %64 = fmul <8 x double> %wide.load412, zeroinitializer
  %65 = fadd <8 x double> %63, %64
  %scevgep28 = getelementptr i8, ptr %scevgep27, i64 %58
  %wide.load413 = load <8 x double>, ptr %scevgep28, align 8, !alias.scope !123
  %66 = fmul <8 x double> %wide.load413, zeroinitializer
  %67 = fadd <8 x double> %65, %66
  %scevgep29 = getelementptr i8, ptr %scevgep28, i64 %58
  %wide.load414 = load <8 x double>, ptr %scevgep29, align 8, !alias.scope !125
  %68 = fmul <8 x double> %wide.load414, zeroinitializer
  %69 = fadd <8 x double> %67, %68
  %scevgep30 = getelementptr i8, ptr %scevgep29, i64 %58
  %wide.load415 = load <8 x double>, ptr %scevgep30, align 8, !alias.scope !127
  %70 = fmul <8 x double> %wide.load415, splat (double 0x3FE2228765F0A2EB)
  %71 = fadd <8 x double> %69, %70
  %scevgep31 = getelementptr i8, ptr %scevgep30, i64 %58
  %wide.load416 = load <8 x double>, ptr %scevgep31, align 8, !alias.scope !129
  %72 = fmul <8 x double> %wide.load416, splat (double 0x40088D35A1175376)
  %73 = fsub <8 x double> %71, %72
  %scevgep32 = getelementptr i8, ptr %scevgep31, i64 %58
  %wide.load417 = load <8 x double>, ptr %scevgep32, align 8, !alias.scope !131
  %74 = fmul <8 x double> %wide.load417, splat (double 0x400313CCA2E462EC)
  %75 = fadd <8 x double> %73, %74
  %scevgep33 = getelementptr i8, ptr %scevgep32, i64 %58
  %wide.load418 = load <8 x double>, ptr %scevgep33, align 8, !alias.scope !133
  %76 = fmul <8 x double> %wide.load418, splat (double 0x4000EFAFD3C0D1BD)
  %77 = fadd <8 x double> %75, %76
  %scevgep34 = getelementptr i8, ptr %scevgep33, i64 %58
  %wide.load419 = load <8 x double>, ptr %scevgep34, align 8, !alias.scope !135
  %78 = fmul <8 x double> %wide.load419, splat (double 0x3FEBE2709A4AC0D3)
  %79 = fsub <8 x double> %77, %78
  %scevgep35 = getelementptr i8, ptr %scevgep34, i64 %58
  %wide.load420 = load <8 x double>, ptr %scevgep35, align 8, !alias.scope !137
  %80 = fmul <8 x double> %wide.load420, splat (double 0x4001EC6A759DA28B)
  %81 = fadd <8 x double> %79, %80
  %scevgep36 = getelementptr i8, ptr %scevgep35, i64 %58
  %wide.load421 = load <8 x double>, ptr %scevgep36, align 8, !alias.scope !139
  %82 = fmul <8 x double> %wide.load421, splat (double 0x3FE435E4B2F53319)
  %83 = fadd <8 x double> %81, %82
  %scevgep37 = getelementptr i8, ptr %scevgep36, i64 %58
  %wide.load422 = load <8 x double>, ptr %scevgep37, align 8, !alias.scope !141
  %84 = fmul <8 x double> %wide.load422, splat (double 0x3FB6C81218B7F07C)
  %85 = fsub <8 x double> %83, %84
  %scevgep38 = getelementptr i8, ptr %scevgep37, i64 %58
  %wide.load423 = load <8 x double>, ptr %scevgep38, align 8, !alias.scope !143
  %86 = fmul <8 x double> %wide.load423, splat (double 0x40322604753358B4)
  %87 = fadd <8 x double> %85, %86
  %scevgep39 = getelementptr i8, ptr %scevgep38, i64 %58
  %wide.load424 = load <8 x double>, ptr %scevgep39, align 8, !alias.scope !145
  %88 = fmul <8 x double> %wide.load424, splat (double 0x402263A6DB60DFA1)
  %89 = fsub <8 x double> %87, %88
  %scevgep40 = getelementptr i8, ptr %scevgep39, i64 %58
  %wide.load425 = load <8 x double>, ptr %scevgep40, align 8, !alias.scope !147
  %90 = fmul <8 x double> %wide.load425, splat (double 0x4011BE8052A2581D)
  %91 = fsub <8 x double> %89, %90
  %92 = fmul <8 x double> %broadcast.splat407, %91
  %93 = shl i64 %index409, 3
  %scevgep25 = getelementptr i8, ptr %scevgep84, i64 %93
  store <8 x double> %92, ptr %scevgep25, align 8, !alias.scope !149, !noalias !151
  %94 = fmul <8 x double> %wide.load410, splat (double 0x4024DAE269AD44FC)
  %95 = fadd <8 x double> %94, zeroinitializer
  %96 = fadd <8 x double> %95, %62
  %97 = fadd <8 x double> %96, %64
  %98 = fadd <8 x double> %97, %66
  %99 = fadd <8 x double> %98, %68
  %100 = fmul <8 x double> %wide.load415, splat (double 0x406E49125D57ED67)
  %101 = fadd <8 x double> %99, %100
  %102 = fmul <8 x double> %wide.load416, splat (double 0x4064A66A19B8434B)
  %103 = fadd <8 x double> %101, %102
  %104 = fmul <8 x double> %wide.load417, splat (double 0x407768BF81E14E35)
  %105 = fsub <8 x double> %103, %104
  %106 = fmul <8 x double> %wide.load418, splat (double 0x40361D194558CFFB)
  %107 = fsub <8 x double> %105, %106
  %108 = fmul <8 x double> %wide.load419, splat (double 0x401EEF08F933A023)
  %109 = fadd <8 x double> %107, %108
  %110 = fmul <8 x double> %wide.load420, splat (double 0x403EAC90D122C30D)
  %111 = fsub <8 x double> %109, %110
  %112 = fmul <8 x double> %wide.load421, splat (double 0x4022AA0D032A0ACD)
  %113 = fsub <8 x double> %111, %112
  %114 = fmul <8 x double> %wide.load422, splat (double 0x402F64FC65250F7C)
  %115 = fadd <8 x double> %113, %114
  %116 = fmul <8 x double> %wide.load423, splat (double 0x403F23AFEDECFD53)
  %117 = fsub <8 x double> %115, %116
  %118 = fmul <8 x double> %wide.load424, splat (double 0x4022B4B2806665CA)
  %119 = fsub <8 x double> %117, %118
  %120 = fmul <8 x double> %wide.load425, splat (double 0x4041E88E43070A10)
  %121 = fadd <8 x double> %119, %120
  %122 = fmul <8 x double> %broadcast.splat407, %121
  %123 = shl i64 %index409, 3
  %scevgep24 = getelementptr i8, ptr %scevgep86, i64 %123
  store <8 x double> %122, ptr %scevgep24, align 8, !alias.scope !155, !noalias !156
  %124 = fmul <8 x double> %wide.load410, splat (double 0x4033FC2C7303381F)
  %125 = fadd <8 x double> %124, zeroinitializer
  %126 = fadd <8 x double> %125, %62
  %127 = fadd <8 x double> %126, %64
  %128 = fadd <8 x double> %127, %66
  %129 = fadd <8 x double> %128, %68
  %130 = fmul <8 x double> %wide.load415, splat (double 0x40783098D10F2521)
  %131 = fsub <8 x double> %129, %130
  %132 = fmul <8 x double> %wide.load416, splat (double 0x4067A5B34EDF4D39)
  %133 = fsub <8 x double> %131, %132
  %134 = fmul <8 x double> %wide.load417, splat (double 0x40807E771C2C6A0C)
  %135 = fadd <8 x double> %133, %134
  %136 = fmul <8 x double> %wide.load418, splat (double 0x402725D68DC06F96)
  %137 = fsub <8 x double> %135, %136
  %138 = fmul <8 x double> %wide.load419, splat (double 0x401B8661DD0F8BD7)
  %139 = fadd <8 x double> %137, %138
  %140 = fmul <8 x double> %wide.load420, splat (double 0x3FF0027A7D67FC68)
  %141 = fsub <8 x double> %139, %140
  %142 = fmul <8 x double> %wide.load421, splat (double 0x3FE8E308023D3331)
  %143 = fadd <8 x double> %141, %142
  %144 = fmul <8 x double> %wide.load422, splat (double 0x400639C3EFFF56D2)
  %145 = fsub <8 x double> %143, %144
  %146 = fmul <8 x double> %wide.load423, splat (double 0x404E192D4F30C77F)
  %147 = fsub <8 x double> %145, %146
  %148 = fmul <8 x double> %wide.load424, splat (double 0x40551481861928C0)
  %149 = fadd <8 x double> %147, %148
  %150 = fmul <8 x double> %wide.load425, splat (double 0x4027FC0D95740812)
  %151 = fadd <8 x double> %149, %150
  %152 = fmul <8 x double> %broadcast.splat407, %151
  %153 = shl i64 %index409, 3
  %scevgep17 = getelementptr i8, ptr %scevgep88, i64 %153
  store <8 x double> %152, ptr %scevgep17, align 8, !alias.scope !157, !noalias !158
  %154 = fmul <8 x double> %wide.load410, splat (double 0x4039B1A59F97E9A3)
  %155 = fsub <8 x double> zeroinitializer, %154
  %156 = fadd <8 x double> %155, %62
  %157 = fadd <8 x double> %156, %64
  %158 = fadd <8 x double> %157, %66
  %159 = fadd <8 x double> %158, %68
  %160 = fmul <8 x double> %wide.load415, splat (double 0x406346126BD860C7)
  %161 = fsub <8 x double> %159, %160
  %162 = fmul <8 x double> %wide.load416, splat (double 0x406CF0F0AC990990)
  %163 = fsub <8 x double> %161, %162
  %164 = fmul <8 x double> %wide.load417, splat (double 0x40765A39D3B3C602)
  %165 = fadd <8 x double> %163, %164
  %166 = fmul <8 x double> %wide.load418, splat (double 0x405759F0D4D83C70)
  %167 = fadd <8 x double> %165, %166
  %168 = fmul <8 x double> %wide.load419, splat (double 0x4042BAAA552107AB)
  %169 = fsub <8 x double> %167, %168
  %170 = fmul <8 x double> %wide.load420, splat (double 0x405A0660A855838E)
  %171 = fadd <8 x double> %169, %170
  %172 = fmul <8 x double> %wide.load421, splat (double 0x403DD71D78528CF6)
  %173 = fadd <8 x double> %171, %172
  %174 = fmul <8 x double> %wide.load422, splat (double 0x4045C4484E37F77E)
  %175 = fsub <8 x double> %173, %174
  %176 = fmul <8 x double> %wide.load423, splat (double 0x405814C57DF82010)
  %177 = fadd <8 x double> %175, %176
  %178 = fmul <8 x double> %wide.load424, splat (double 0x404396B082B5CD1E)
  %179 = fsub <8 x double> %177, %178
  %180 = fmul <8 x double> %wide.load425, splat (double 0x4062B7423E1CB30D)
  %181 = fsub <8 x double> %179, %180
  %182 = fmul <8 x double> %broadcast.splat407, %181
  %183 = shl i64 %index409, 3
  %scevgep16 = getelementptr i8, ptr %scevgep90, i64 %183
  store <8 x double> %182, ptr %scevgep16, align 8, !alias.scope !159, !noalias !160
  %index.next474 = add nuw nsw i64 %index409, 8
  %184 = icmp eq i64 %n.vec405, %index.next474
  br i1 %184, label %middle.block475, label %vector.body408, !llvm.loop !161

middle.block475:                                  ; preds = %vector.body408
  %cmp.n476 = icmp eq i64 %arg.y.2, %n.vec405
  br i1 %cmp.n476, label %B13410157, label %B326.endif.endif.us.preheader478

B326.endif.endif.us.preheader478:                 ; preds = %middle.block475, %vector.memcheck83, %B326.endif.endif.us.preheader
  %.1078643653.us.ph = phi i64 [ 0, %vector.memcheck83 ], [ 0, %B326.endif.endif.us.preheader ], [ %n.vec405, %middle.block475 ]
  %185 = shl i64 %.1078643653.us.ph, 3
  %scevgep480 = getelementptr i8, ptr %arg.K.4, i64 %185
  %186 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.15.idx
  %scevgep482 = getelementptr i8, ptr %186, i64 %185
  %187 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.14.idx
  %scevgep484 = getelementptr i8, ptr %187, i64 %185
  %188 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.13.idx
  %scevgep486 = getelementptr i8, ptr %188, i64 %185
  %scevgep488 = getelementptr i8, ptr %.407, i64 %185
  %189 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.11.idx
  %scevgep490 = getelementptr i8, ptr %189, i64 %185
  %190 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.10.idx
  %scevgep492 = getelementptr i8, ptr %190, i64 %185
  %191 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.9.idx
  %scevgep494 = getelementptr i8, ptr %191, i64 %185
  %192 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.8.idx
  %scevgep496 = getelementptr i8, ptr %192, i64 %185
  %193 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.7.idx
  %scevgep498 = getelementptr i8, ptr %193, i64 %185
  %194 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.6.idx
  %scevgep500 = getelementptr i8, ptr %194, i64 %185
  %195 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.5.idx
  %scevgep502 = getelementptr i8, ptr %195, i64 %185
  %196 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.4.idx
  %scevgep504 = getelementptr i8, ptr %196, i64 %185
  %197 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.3.idx
  %scevgep506 = getelementptr i8, ptr %197, i64 %185
  %198 = getelementptr i8, ptr %arg.K.4, i64 %gep622.us.us.2.idx
  %scevgep508 = getelementptr i8, ptr %198, i64 %185
  %199 = add i64 %.1078643653.us.ph, %arg.K.5.1
  %200 = shl i64 %199, 3
  %scevgep510 = getelementptr i8, ptr %arg.K.4, i64 %200
  %201 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.3.idx
  %scevgep512 = getelementptr i8, ptr %201, i64 %185
  %202 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.2.idx
  %scevgep514 = getelementptr i8, ptr %202, i64 %185
  %203 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.1.idx
  %scevgep516 = getelementptr i8, ptr %203, i64 %185
  %204 = getelementptr i8, ptr %arg.F.4, i64 %gep638.us.us.idx
  %scevgep518 = getelementptr i8, ptr %204, i64 %185
  %205 = sub i64 %arg.y.2, %.1078643653.us.ph
  br label %B326.endif.endif.us

B326.endif.endif.us:                              ; preds = %B326.endif.endif.us, %B326.endif.endif.us.preheader478
  %lsr.iv = phi i64 [ 0, %B326.endif.endif.us.preheader478 ], [ %lsr.iv.next, %B326.endif.endif.us ]
  %206 = shl i64 %lsr.iv, 3
  %scevgep481 = getelementptr i8, ptr %scevgep480, i64 %206
  %scevgep511 = getelementptr i8, ptr %scevgep510, i64 %206
  %scevgep509 = getelementptr i8, ptr %scevgep508, i64 %206
  %scevgep507 = getelementptr i8, ptr %scevgep506, i64 %206
  %scevgep505 = getelementptr i8, ptr %scevgep504, i64 %206
  %207 = shl i64 %lsr.iv, 3
  %scevgep15 = getelementptr i8, ptr %scevgep502, i64 %207
  %208 = shl i64 %lsr.iv, 3
  %scevgep14 = getelementptr i8, ptr %scevgep500, i64 %208
  %209 = shl i64 %lsr.iv, 3
  %scevgep13 = getelementptr i8, ptr %scevgep498, i64 %209
  %210 = shl i64 %lsr.iv, 3
  %scevgep12 = getelementptr i8, ptr %scevgep496, i64 %210
  %211 = shl i64 %lsr.iv, 3
  %scevgep11 = getelementptr i8, ptr %scevgep494, i64 %211
  %212 = shl i64 %lsr.iv, 3
  %scevgep10 = getelementptr i8, ptr %scevgep492, i64 %212
  %213 = shl i64 %lsr.iv, 3
  %scevgep9 = getelementptr i8, ptr %scevgep490, i64 %213
  %214 = shl i64 %lsr.iv, 3
  %scevgep8 = getelementptr i8, ptr %scevgep488, i64 %214
  %215 = shl i64 %lsr.iv, 3
  %scevgep7 = getelementptr i8, ptr %scevgep486, i64 %215
  %216 = shl i64 %lsr.iv, 3
  %scevgep6 = getelementptr i8, ptr %scevgep484, i64 %216
  %217 = shl i64 %lsr.iv, 3
  %scevgep5 = getelementptr i8, ptr %scevgep482, i64 %217
  %.1495.us.us = load double, ptr %scevgep481, align 8
  %.1498.us.us = fmul double %.1495.us.us, 0x4020DB9DCC37C81B
  %218 = fsub double 0.000000e+00, %.1498.us.us
  %.1495.us.us.1 = load double, ptr %scevgep511, align 8
  %.1498.us.us.1 = fmul double %.1495.us.us.1, 0.000000e+00
  %.1500.us.us.1 = fadd double %218, %.1498.us.us.1
  %.1495.us.us.2 = load double, ptr %scevgep509, align 8
  %.1498.us.us.2 = fmul double %.1495.us.us.2, 0.000000e+00
  %.1500.us.us.2 = fadd double %.1500.us.us.1, %.1498.us.us.2
  %.1495.us.us.3 = load double, ptr %scevgep507, align 8
  %.1498.us.us.3 = fmul double %.1495.us.us.3, 0.000000e+00
  %.1500.us.us.3 = fadd double %.1500.us.us.2, %.1498.us.us.3
  %.1495.us.us.4 = load double, ptr %scevgep505, align 8
  %.1498.us.us.4 = fmul double %.1495.us.us.4, 0.000000e+00
  %.1500.us.us.4 = fadd double %.1500.us.us.3, %.1498.us.us.4
  %.1495.us.us.5 = load double, ptr %scevgep15, align 8
  %.1498.us.us.5 = fmul double %.1495.us.us.5, 0x3FE2228765F0A2EB
  %.1500.us.us.5 = fadd double %.1500.us.us.4, %.1498.us.us.5
  %.1495.us.us.6 = load double, ptr %scevgep14, align 8
  %.1498.us.us.6 = fmul double %.1495.us.us.6, 0x40088D35A1175376
  %219 = fsub double %.1500.us.us.5, %.1498.us.us.6
  %.1495.us.us.7 = load double, ptr %scevgep13, align 8
  %.1498.us.us.7 = fmul double %.1495.us.us.7, 0x400313CCA2E462EC
  %.1500.us.us.7 = fadd double %219, %.1498.us.us.7
  %.1495.us.us.8 = load double, ptr %scevgep12, align 8
  %.1498.us.us.8 = fmul double %.1495.us.us.8, 0x4000EFAFD3C0D1BD
  %.1500.us.us.8 = fadd double %.1500.us.us.7, %.1498.us.us.8
  %.1495.us.us.9 = load double, ptr %scevgep11, align 8
  %.1498.us.us.9 = fmul double %.1495.us.us.9, 0x3FEBE2709A4AC0D3
  %220 = fsub double %.1500.us.us.8, %.1498.us.us.9
  %.1495.us.us.10 = load double, ptr %scevgep10, align 8
  %.1498.us.us.10 = fmul double %.1495.us.us.10, 0x4001EC6A759DA28B
  %.1500.us.us.10 = fadd double %220, %.1498.us.us.10
  %.1495.us.us.11 = load double, ptr %scevgep9, align 8
  %.1498.us.us.11 = fmul double %.1495.us.us.11, 0x3FE435E4B2F53319
  %.1500.us.us.11 = fadd double %.1500.us.us.10, %.1498.us.us.11
  %.1495.us.us.12 = load double, ptr %scevgep8, align 8
  %.1498.us.us.12 = fmul double %.1495.us.us.12, 0x3FB6C81218B7F07C
  %221 = fsub double %.1500.us.us.11, %.1498.us.us.12
  %.1495.us.us.13 = load double, ptr %scevgep7, align 8
  %.1498.us.us.13 = fmul double %.1495.us.us.13, 0x40322604753358B4
  %.1500.us.us.13 = fadd double %221, %.1498.us.us.13
  %.1495.us.us.14 = load double, ptr %scevgep6, align 8
  %.1498.us.us.14 = fmul double %.1495.us.us.14, 0x402263A6DB60DFA1
  %222 = fsub double %.1500.us.us.13, %.1498.us.us.14
  %.1495.us.us.15 = load double, ptr %scevgep5, align 8
  %.1498.us.us.15 = fmul double %.1495.us.us.15, 0x4011BE8052A2581D
  %223 = fsub double %222, %.1498.us.us.15
  %.1510.us.us = fmul double %arg.h, %223
  %224 = shl i64 %lsr.iv, 3
  %scevgep4 = getelementptr i8, ptr %scevgep518, i64 %224
  store double %.1510.us.us, ptr %scevgep4, align 8
  %.1495.us.us.17 = load double, ptr %scevgep481, align 8
  %.1498.us.us.18 = fmul double %.1495.us.us.17, 0x4024DAE269AD44FC
  %.1500.us.us.19 = fadd double %.1498.us.us.18, 0.000000e+00
  %.1495.us.us.1.1 = load double, ptr %scevgep511, align 8
  %.1498.us.us.1.1 = fmul double %.1495.us.us.1.1, 0.000000e+00
  %.1500.us.us.1.1 = fadd double %.1500.us.us.19, %.1498.us.us.1.1
  %.1495.us.us.2.1 = load double, ptr %scevgep509, align 8
  %.1498.us.us.2.1 = fmul double %.1495.us.us.2.1, 0.000000e+00
  %.1500.us.us.2.1 = fadd double %.1500.us.us.1.1, %.1498.us.us.2.1
  %.1495.us.us.3.1 = load double, ptr %scevgep507, align 8
  %.1498.us.us.3.1 = fmul double %.1495.us.us.3.1, 0.000000e+00
  %.1500.us.us.3.1 = fadd double %.1500.us.us.2.1, %.1498.us.us.3.1
  %.1495.us.us.4.1 = load double, ptr %scevgep505, align 8
  %.1498.us.us.4.1 = fmul double %.1495.us.us.4.1, 0.000000e+00
  %.1500.us.us.4.1 = fadd double %.1500.us.us.3.1, %.1498.us.us.4.1
  %.1495.us.us.5.1 = load double, ptr %scevgep15, align 8
  %.1498.us.us.5.1 = fmul double %.1495.us.us.5.1, 0x406E49125D57ED67
  %.1500.us.us.5.1 = fadd double %.1500.us.us.4.1, %.1498.us.us.5.1
  %.1495.us.us.6.1 = load double, ptr %scevgep14, align 8
  %.1498.us.us.6.1 = fmul double %.1495.us.us.6.1, 0x4064A66A19B8434B
  %.1500.us.us.6.1 = fadd double %.1500.us.us.5.1, %.1498.us.us.6.1
  %.1495.us.us.7.1 = load double, ptr %scevgep13, align 8
  %.1498.us.us.7.1 = fmul double %.1495.us.us.7.1, 0x407768BF81E14E35
  %225 = fsub double %.1500.us.us.6.1, %.1498.us.us.7.1
  %.1495.us.us.8.1 = load double, ptr %scevgep12, align 8
  %.1498.us.us.8.1 = fmul double %.1495.us.us.8.1, 0x40361D194558CFFB
  %226 = fsub double %225, %.1498.us.us.8.1
  %.1495.us.us.9.1 = load double, ptr %scevgep11, align 8
  %.1498.us.us.9.1 = fmul double %.1495.us.us.9.1, 0x401EEF08F933A023
  %.1500.us.us.9.1 = fadd double %226, %.1498.us.us.9.1
  %.1495.us.us.10.1 = load double, ptr %scevgep10, align 8
  %.1498.us.us.10.1 = fmul double %.1495.us.us.10.1, 0x403EAC90D122C30D
  %227 = fsub double %.1500.us.us.9.1, %.1498.us.us.10.1
  %.1495.us.us.11.1 = load double, ptr %scevgep9, align 8
  %.1498.us.us.11.1 = fmul double %.1495.us.us.11.1, 0x4022AA0D032A0ACD
  %228 = fsub double %227, %.1498.us.us.11.1
  %.1495.us.us.12.1 = load double, ptr %scevgep8, align 8
  %.1498.us.us.12.1 = fmul double %.1495.us.us.12.1, 0x402F64FC65250F7C
  %.1500.us.us.12.1 = fadd double %228, %.1498.us.us.12.1
  %.1495.us.us.13.1 = load double, ptr %scevgep7, align 8
  %.1498.us.us.13.1 = fmul double %.1495.us.us.13.1, 0x403F23AFEDECFD53
  %229 = fsub double %.1500.us.us.12.1, %.1498.us.us.13.1
  %.1495.us.us.14.1 = load double, ptr %scevgep6, align 8
  %.1498.us.us.14.1 = fmul double %.1495.us.us.14.1, 0x4022B4B2806665CA
  %230 = fsub double %229, %.1498.us.us.14.1
  %.1495.us.us.15.1 = load double, ptr %scevgep5, align 8
  %.1498.us.us.15.1 = fmul double %.1495.us.us.15.1, 0x4041E88E43070A10
  %.1500.us.us.15.1 = fadd double %230, %.1498.us.us.15.1
  %.1510.us.us.1 = fmul double %arg.h, %.1500.us.us.15.1
  %231 = shl i64 %lsr.iv, 3
  %scevgep3 = getelementptr i8, ptr %scevgep516, i64 %231
  store double %.1510.us.us.1, ptr %scevgep3, align 8
  %.1495.us.us.211 = load double, ptr %scevgep481, align 8
  %.1498.us.us.212 = fmul double %.1495.us.us.211, 0x4033FC2C7303381F
  %.1500.us.us.213 = fadd double %.1498.us.us.212, 0.000000e+00
  %.1495.us.us.1.2 = load double, ptr %scevgep511, align 8
  %.1498.us.us.1.2 = fmul double %.1495.us.us.1.2, 0.000000e+00
  %.1500.us.us.1.2 = fadd double %.1500.us.us.213, %.1498.us.us.1.2
  %.1495.us.us.2.2 = load double, ptr %scevgep509, align 8
  %.1498.us.us.2.2 = fmul double %.1495.us.us.2.2, 0.000000e+00
  %.1500.us.us.2.2 = fadd double %.1500.us.us.1.2, %.1498.us.us.2.2
  %.1495.us.us.3.2 = load double, ptr %scevgep507, align 8
  %.1498.us.us.3.2 = fmul double %.1495.us.us.3.2, 0.000000e+00
  %.1500.us.us.3.2 = fadd double %.1500.us.us.2.2, %.1498.us.us.3.2
  %.1495.us.us.4.2 = load double, ptr %scevgep505, align 8
  %.1498.us.us.4.2 = fmul double %.1495.us.us.4.2, 0.000000e+00
  %.1500.us.us.4.2 = fadd double %.1500.us.us.3.2, %.1498.us.us.4.2
  %.1495.us.us.5.2 = load double, ptr %scevgep15, align 8
  %.1498.us.us.5.2 = fmul double %.1495.us.us.5.2, 0x40783098D10F2521
  %232 = fsub double %.1500.us.us.4.2, %.1498.us.us.5.2
  %.1495.us.us.6.2 = load double, ptr %scevgep14, align 8
  %.1498.us.us.6.2 = fmul double %.1495.us.us.6.2, 0x4067A5B34EDF4D39
  %233 = fsub double %232, %.1498.us.us.6.2
  %.1495.us.us.7.2 = load double, ptr %scevgep13, align 8
  %.1498.us.us.7.2 = fmul double %.1495.us.us.7.2, 0x40807E771C2C6A0C
  %.1500.us.us.7.2 = fadd double %233, %.1498.us.us.7.2
  %.1495.us.us.8.2 = load double, ptr %scevgep12, align 8
  %.1498.us.us.8.2 = fmul double %.1495.us.us.8.2, 0x402725D68DC06F96
  %234 = fsub double %.1500.us.us.7.2, %.1498.us.us.8.2
  %.1495.us.us.9.2 = load double, ptr %scevgep11, align 8
  %.1498.us.us.9.2 = fmul double %.1495.us.us.9.2, 0x401B8661DD0F8BD7
  %.1500.us.us.9.2 = fadd double %234, %.1498.us.us.9.2
  %.1495.us.us.10.2 = load double, ptr %scevgep10, align 8
  %.1498.us.us.10.2 = fmul double %.1495.us.us.10.2, 0x3FF0027A7D67FC68
  %235 = fsub double %.1500.us.us.9.2, %.1498.us.us.10.2
  %.1495.us.us.11.2 = load double, ptr %scevgep9, align 8
  %.1498.us.us.11.2 = fmul double %.1495.us.us.11.2, 0x3FE8E308023D3331
  %.1500.us.us.11.2 = fadd double %235, %.1498.us.us.11.2
  %.1495.us.us.12.2 = load double, ptr %scevgep8, align 8
  %.1498.us.us.12.2 = fmul double %.1495.us.us.12.2, 0x400639C3EFFF56D2
  %236 = fsub double %.1500.us.us.11.2, %.1498.us.us.12.2
  %.1495.us.us.13.2 = load double, ptr %scevgep7, align 8
  %.1498.us.us.13.2 = fmul double %.1495.us.us.13.2, 0x404E192D4F30C77F
  %237 = fsub double %236, %.1498.us.us.13.2
  %.1495.us.us.14.2 = load double, ptr %scevgep6, align 8
  %.1498.us.us.14.2 = fmul double %.1495.us.us.14.2, 0x40551481861928C0
  %.1500.us.us.14.2 = fadd double %237, %.1498.us.us.14.2
  %.1495.us.us.15.2 = load double, ptr %scevgep5, align 8
  %.1498.us.us.15.2 = fmul double %.1495.us.us.15.2, 0x4027FC0D95740812
  %.1500.us.us.15.2 = fadd double %.1500.us.us.14.2, %.1498.us.us.15.2
  %.1510.us.us.2 = fmul double %arg.h, %.1500.us.us.15.2
  %238 = shl i64 %lsr.iv, 3
  %scevgep2 = getelementptr i8, ptr %scevgep514, i64 %238
  store double %.1510.us.us.2, ptr %scevgep2, align 8
  %.1495.us.us.315 = load double, ptr %scevgep481, align 8
  %.1498.us.us.316 = fmul double %.1495.us.us.315, 0x4039B1A59F97E9A3
  %239 = fsub double 0.000000e+00, %.1498.us.us.316
  %.1495.us.us.1.3 = load double, ptr %scevgep511, align 8
  %.1498.us.us.1.3 = fmul double %.1495.us.us.1.3, 0.000000e+00
  %.1500.us.us.1.3 = fadd double %239, %.1498.us.us.1.3
  %.1495.us.us.2.3 = load double, ptr %scevgep509, align 8
  %.1498.us.us.2.3 = fmul double %.1495.us.us.2.3, 0.000000e+00
  %.1500.us.us.2.3 = fadd double %.1500.us.us.1.3, %.1498.us.us.2.3
  %.1495.us.us.3.3 = load double, ptr %scevgep507, align 8
  %.1498.us.us.3.3 = fmul double %.1495.us.us.3.3, 0.000000e+00
  %.1500.us.us.3.3 = fadd double %.1500.us.us.2.3, %.1498.us.us.3.3
  %.1495.us.us.4.3 = load double, ptr %scevgep505, align 8
  %.1498.us.us.4.3 = fmul double %.1495.us.us.4.3, 0.000000e+00
  %.1500.us.us.4.3 = fadd double %.1500.us.us.3.3, %.1498.us.us.4.3
  %.1495.us.us.5.3 = load double, ptr %scevgep15, align 8
  %.1498.us.us.5.3 = fmul double %.1495.us.us.5.3, 0x406346126BD860C7
  %240 = fsub double %.1500.us.us.4.3, %.1498.us.us.5.3
  %.1495.us.us.6.3 = load double, ptr %scevgep14, align 8
  %.1498.us.us.6.3 = fmul double %.1495.us.us.6.3, 0x406CF0F0AC990990
  %241 = fsub double %240, %.1498.us.us.6.3
  %.1495.us.us.7.3 = load double, ptr %scevgep13, align 8
  %.1498.us.us.7.3 = fmul double %.1495.us.us.7.3, 0x40765A39D3B3C602
  %.1500.us.us.7.3 = fadd double %241, %.1498.us.us.7.3
  %.1495.us.us.8.3 = load double, ptr %scevgep12, align 8
  %.1498.us.us.8.3 = fmul double %.1495.us.us.8.3, 0x405759F0D4D83C70
  %.1500.us.us.8.3 = fadd double %.1500.us.us.7.3, %.1498.us.us.8.3
  %.1495.us.us.9.3 = load double, ptr %scevgep11, align 8
  %.1498.us.us.9.3 = fmul double %.1495.us.us.9.3, 0x4042BAAA552107AB
  %242 = fsub double %.1500.us.us.8.3, %.1498.us.us.9.3
  %.1495.us.us.10.3 = load double, ptr %scevgep10, align 8
  %.1498.us.us.10.3 = fmul double %.1495.us.us.10.3, 0x405A0660A855838E
  %.1500.us.us.10.3 = fadd double %242, %.1498.us.us.10.3
  %.1495.us.us.11.3 = load double, ptr %scevgep9, align 8
  %.1498.us.us.11.3 = fmul double %.1495.us.us.11.3, 0x403DD71D78528CF6
  %.1500.us.us.11.3 = fadd double %.1500.us.us.10.3, %.1498.us.us.11.3
  %.1495.us.us.12.3 = load double, ptr %scevgep8, align 8
  %.1498.us.us.12.3 = fmul double %.1495.us.us.12.3, 0x4045C4484E37F77E
  %243 = fsub double %.1500.us.us.11.3, %.1498.us.us.12.3
  %.1495.us.us.13.3 = load double, ptr %scevgep7, align 8
  %.1498.us.us.13.3 = fmul double %.1495.us.us.13.3, 0x405814C57DF82010
  %.1500.us.us.13.3 = fadd double %243, %.1498.us.us.13.3
  %.1495.us.us.14.3 = load double, ptr %scevgep6, align 8
  %.1498.us.us.14.3 = fmul double %.1495.us.us.14.3, 0x404396B082B5CD1E
  %244 = fsub double %.1500.us.us.13.3, %.1498.us.us.14.3
  %.1495.us.us.15.3 = load double, ptr %scevgep5, align 8
  %.1498.us.us.15.3 = fmul double %.1495.us.us.15.3, 0x4062B7423E1CB30D
  %245 = fsub double %244, %.1498.us.us.15.3
  %.1510.us.us.3 = fmul double %arg.h, %245
  %246 = shl i64 %lsr.iv, 3
  %scevgep1 = getelementptr i8, ptr %scevgep512, i64 %246
  store double %.1510.us.us.3, ptr %scevgep1, align 8
  %lsr.iv.next = add i64 %lsr.iv, 1
  %exitcond670.not = icmp eq i64 %205, %lsr.iv.next
  br i1 %exitcond670.not, label %B13410157, label %B326.endif.endif.us, !llvm.loop !162
}

; Function Attrs: nofree norecurse nosync nounwind memory(argmem: readwrite)
define linkonce_odr noundef i32 @_ZN6charts7solvers2rk10dense_evalB3v94B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias readnone captures(none) %excinfo, ptr readnone captures(none) %arg.F.0, ptr readnone captures(none) %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr readonly captures(none) %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1, ptr readnone captures(none) %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, double %arg.x, ptr readnone captures(none) %arg.out.0, ptr readnone captures(none) %arg.out.1, i64 %arg.out.2, i64 %arg.out.3, ptr writeonly captures(none) %arg.out.4, i64 %arg.out.5.0, i64 %arg.out.6.0) local_unnamed_addr #2 {
B0.endif:
  %.143175.not = icmp slt i64 %arg.y.2, 1
  br i1 %.143175.not, label %B236, label %B50.endif.endif.lr.ph

B50.endif.endif.lr.ph:                            ; preds = %B0.endif
  %.423 = fsub double 1.000000e+00, %arg.x
  %gep164.idx = mul i64 %arg.F.5.1, 48
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 16
  br i1 %min.iters.check, label %B50.endif.endif.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %B50.endif.endif.lr.ph
  %gep164.4.idx = shl i64 %arg.F.5.1, 4
  %gep164.3.idx.neg = mul i64 %arg.F.5.1, -24
  %gep164.2.idx = shl i64 %arg.F.5.1, 5
  %gep164.1.idx.neg = mul i64 %arg.F.5.1, -40
  %0 = ptrtoint ptr %arg.out.4 to i64
  %1 = ptrtoint ptr %arg.F.4 to i64
  %2 = ptrtoint ptr %arg.y.4 to i64
  %3 = sub i64 %0, %1
  %diff.check = icmp ult i64 %3, 64
  %4 = shl i64 %arg.F.5.1, 3
  %5 = sub i64 %3, %4
  %diff.check3 = icmp ult i64 %5, 64
  %conflict.rdx = or i1 %diff.check, %diff.check3
  %6 = sub i64 %3, %gep164.4.idx
  %diff.check4 = icmp ult i64 %6, 64
  %conflict.rdx5 = or i1 %diff.check4, %conflict.rdx
  %7 = add i64 %3, %gep164.3.idx.neg
  %diff.check6 = icmp ult i64 %7, 64
  %conflict.rdx7 = or i1 %diff.check6, %conflict.rdx5
  %8 = sub i64 %3, %gep164.2.idx
  %diff.check8 = icmp ult i64 %8, 64
  %conflict.rdx9 = or i1 %diff.check8, %conflict.rdx7
  %9 = add i64 %3, %gep164.1.idx.neg
  %diff.check10 = icmp ult i64 %9, 64
  %conflict.rdx11 = or i1 %diff.check10, %conflict.rdx9
  %10 = sub i64 %3, %gep164.idx
  %diff.check12 = icmp ult i64 %10, 64
  %conflict.rdx13 = or i1 %diff.check12, %conflict.rdx11
  %11 = sub i64 %0, %2
  %diff.check15 = icmp ult i64 %11, 64
  %conflict.rdx16 = or i1 %diff.check15, %conflict.rdx13
  br i1 %conflict.rdx16, label %B50.endif.endif.preheader, label %vector.ph

vector.ph:                                        ; preds = %vector.memcheck
  %n.vec = and i64 %arg.y.2, 9223372036854775800
  %broadcast.splatinsert = insertelement <8 x double> poison, double %.423, i64 0
  %broadcast.splat = shufflevector <8 x double> %broadcast.splatinsert, <8 x double> poison, <8 x i32> zeroinitializer
  %broadcast.splatinsert17 = insertelement <8 x double> poison, double %arg.x, i64 0
  %broadcast.splat18 = shufflevector <8 x double> %broadcast.splatinsert17, <8 x double> poison, <8 x i32> zeroinitializer
  %scevgep98 = getelementptr i8, ptr %arg.F.4, i64 %gep164.idx
  %12 = mul i64 %arg.F.5.1, -8
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %13 = shl i64 %index, 3
  %scevgep99 = getelementptr i8, ptr %scevgep98, i64 %13
  %wide.load = load <8 x double>, ptr %scevgep99, align 8
  %14 = fadd <8 x double> %wide.load, zeroinitializer
  %15 = fmul <8 x double> %broadcast.splat18, %14
  %scevgep100 = getelementptr i8, ptr %scevgep99, i64 %12
  %wide.load19 = load <8 x double>, ptr %scevgep100, align 8
  %16 = fadd <8 x double> %wide.load19, %15
  %17 = fmul <8 x double> %broadcast.splat, %16
  %scevgep101 = getelementptr i8, ptr %scevgep100, i64 %12
  %wide.load20 = load <8 x double>, ptr %scevgep101, align 8
  %18 = fadd <8 x double> %wide.load20, %17
  %19 = fmul <8 x double> %broadcast.splat18, %18
  %scevgep102 = getelementptr i8, ptr %scevgep101, i64 %12
  %wide.load21 = load <8 x double>, ptr %scevgep102, align 8
  %20 = fadd <8 x double> %wide.load21, %19
  %21 = fmul <8 x double> %broadcast.splat, %20
  %scevgep103 = getelementptr i8, ptr %scevgep102, i64 %12
  %wide.load22 = load <8 x double>, ptr %scevgep103, align 8
  %22 = fadd <8 x double> %wide.load22, %21
  %23 = fmul <8 x double> %broadcast.splat18, %22
  %scevgep104 = getelementptr i8, ptr %scevgep103, i64 %12
  %wide.load23 = load <8 x double>, ptr %scevgep104, align 8
  %24 = fadd <8 x double> %wide.load23, %23
  %25 = fmul <8 x double> %broadcast.splat, %24
  %scevgep105 = getelementptr i8, ptr %scevgep104, i64 %12
  %wide.load24 = load <8 x double>, ptr %scevgep105, align 8
  %26 = fadd <8 x double> %wide.load24, %25
  %27 = fmul <8 x double> %broadcast.splat18, %26
  %28 = shl i64 %index, 3
  %scevgep23 = getelementptr i8, ptr %arg.y.4, i64 %28
  %wide.load25 = load <8 x double>, ptr %scevgep23, align 8
  %29 = fadd <8 x double> %wide.load25, %27
  %30 = shl i64 %index, 3
  %scevgep22 = getelementptr i8, ptr %arg.out.4, i64 %30
  store <8 x double> %29, ptr %scevgep22, align 8
  %index.next = add nuw nsw i64 %index, 8
  %31 = icmp eq i64 %n.vec, %index.next
  br i1 %31, label %middle.block, label %vector.body, !llvm.loop !163

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %B236, label %B50.endif.endif.preheader

B50.endif.endif.preheader:                        ; preds = %middle.block, %vector.memcheck, %B50.endif.endif.lr.ph
  %.149171176.ph = phi i64 [ 0, %vector.memcheck ], [ 0, %B50.endif.endif.lr.ph ], [ %n.vec, %middle.block ]
  %xtraiter = and i64 %arg.y.2, 3
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B50.endif.endif.prol.loopexit, label %B50.endif.endif.prol.preheader

B50.endif.endif.prol.preheader:                   ; preds = %B50.endif.endif.preheader
  %scevgep88 = getelementptr i8, ptr %arg.F.4, i64 %gep164.idx
  %32 = mul i64 %arg.F.5.1, -8
  br label %B50.endif.endif.prol

B50.endif.endif.prol:                             ; preds = %B50.endif.endif.prol, %B50.endif.endif.prol.preheader
  %lsr.iv = phi i64 [ %xtraiter, %B50.endif.endif.prol.preheader ], [ %lsr.iv.next, %B50.endif.endif.prol ]
  %.149171176.prol = phi i64 [ %.149171176.ph, %B50.endif.endif.prol.preheader ], [ %.156.prol, %B50.endif.endif.prol ]
  %33 = shl i64 %.149171176.prol, 3
  %scevgep89 = getelementptr i8, ptr %scevgep88, i64 %33
  %.357.prol = load double, ptr %scevgep89, align 8
  %.361.prol = fadd double %.357.prol, 0.000000e+00
  %acc.5.2.prol = fmul double %arg.x, %.361.prol
  %scevgep90 = getelementptr i8, ptr %scevgep89, i64 %32
  %.357.1.prol = load double, ptr %scevgep90, align 8
  %.361.1.prol = fadd double %.357.1.prol, %acc.5.2.prol
  %acc.5.2.1.prol = fmul double %.423, %.361.1.prol
  %scevgep91 = getelementptr i8, ptr %scevgep90, i64 %32
  %.357.2.prol = load double, ptr %scevgep91, align 8
  %.361.2.prol = fadd double %.357.2.prol, %acc.5.2.1.prol
  %acc.5.2.2.prol = fmul double %arg.x, %.361.2.prol
  %scevgep92 = getelementptr i8, ptr %scevgep91, i64 %32
  %.357.3.prol = load double, ptr %scevgep92, align 8
  %.361.3.prol = fadd double %.357.3.prol, %acc.5.2.2.prol
  %acc.5.2.3.prol = fmul double %.423, %.361.3.prol
  %scevgep93 = getelementptr i8, ptr %scevgep92, i64 %32
  %.357.4.prol = load double, ptr %scevgep93, align 8
  %.361.4.prol = fadd double %.357.4.prol, %acc.5.2.3.prol
  %acc.5.2.4.prol = fmul double %arg.x, %.361.4.prol
  %scevgep94 = getelementptr i8, ptr %scevgep93, i64 %32
  %.357.5.prol = load double, ptr %scevgep94, align 8
  %.361.5.prol = fadd double %.357.5.prol, %acc.5.2.4.prol
  %acc.5.2.5.prol = fmul double %.423, %.361.5.prol
  %scevgep95 = getelementptr i8, ptr %scevgep94, i64 %32
  %.357.6.prol = load double, ptr %scevgep95, align 8
  %.361.6.prol = fadd double %.357.6.prol, %acc.5.2.5.prol
  %acc.5.2.6.prol = fmul double %arg.x, %.361.6.prol
  %.156.prol = add nuw nsw i64 %.149171176.prol, 1
  %34 = shl i64 %.149171176.prol, 3
  %scevgep21 = getelementptr i8, ptr %arg.y.4, i64 %34
  %.465.prol = load double, ptr %scevgep21, align 8
  %.467.prol = fadd double %.465.prol, %acc.5.2.6.prol
  %35 = shl i64 %.149171176.prol, 3
  %scevgep20 = getelementptr i8, ptr %arg.out.4, i64 %35
  store double %.467.prol, ptr %scevgep20, align 8
  %lsr.iv.next = add nsw i64 %lsr.iv, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next, 0
  br i1 %prol.iter.cmp.not, label %B50.endif.endif.prol.loopexit, label %B50.endif.endif.prol, !llvm.loop !164

B50.endif.endif.prol.loopexit:                    ; preds = %B50.endif.endif.prol, %B50.endif.endif.preheader
  %.149171176.unr = phi i64 [ %.149171176.ph, %B50.endif.endif.preheader ], [ %.156.prol, %B50.endif.endif.prol ]
  %36 = sub nsw i64 %.149171176.ph, %arg.y.2
  %37 = icmp ugt i64 %36, -4
  br i1 %37, label %B236, label %B50.endif.endif.preheader38

B50.endif.endif.preheader38:                      ; preds = %B50.endif.endif.prol.loopexit
  %38 = getelementptr i8, ptr %arg.F.4, i64 %gep164.idx
  %scevgep54 = getelementptr i8, ptr %38, i64 24
  %39 = mul i64 %arg.F.5.1, -8
  br label %B50.endif.endif

B236:                                             ; preds = %B50.endif.endif, %B50.endif.endif.prol.loopexit, %middle.block, %B0.endif
  store ptr null, ptr %retptr, align 8
  ret i32 0

B50.endif.endif:                                  ; preds = %B50.endif.endif, %B50.endif.endif.preheader38
  %.149171176 = phi i64 [ %.156.3, %B50.endif.endif ], [ %.149171176.unr, %B50.endif.endif.preheader38 ]
  %40 = shl i64 %.149171176, 3
  %scevgep58 = getelementptr i8, ptr %scevgep54, i64 %40
  %scevgep59 = getelementptr i8, ptr %scevgep58, i64 -24
  %.357 = load double, ptr %scevgep59, align 8
  %.361 = fadd double %.357, 0.000000e+00
  %acc.5.2 = fmul double %arg.x, %.361
  %scevgep62 = getelementptr i8, ptr %scevgep59, i64 %39
  %.357.1 = load double, ptr %scevgep62, align 8
  %.361.1 = fadd double %.357.1, %acc.5.2
  %acc.5.2.1 = fmul double %.423, %.361.1
  %scevgep63 = getelementptr i8, ptr %scevgep62, i64 %39
  %.357.2 = load double, ptr %scevgep63, align 8
  %.361.2 = fadd double %.357.2, %acc.5.2.1
  %acc.5.2.2 = fmul double %arg.x, %.361.2
  %scevgep64 = getelementptr i8, ptr %scevgep63, i64 %39
  %.357.3 = load double, ptr %scevgep64, align 8
  %.361.3 = fadd double %.357.3, %acc.5.2.2
  %acc.5.2.3 = fmul double %.423, %.361.3
  %scevgep65 = getelementptr i8, ptr %scevgep64, i64 %39
  %.357.4 = load double, ptr %scevgep65, align 8
  %.361.4 = fadd double %.357.4, %acc.5.2.3
  %acc.5.2.4 = fmul double %arg.x, %.361.4
  %scevgep66 = getelementptr i8, ptr %scevgep65, i64 %39
  %.357.5 = load double, ptr %scevgep66, align 8
  %.361.5 = fadd double %.357.5, %acc.5.2.4
  %acc.5.2.5 = fmul double %.423, %.361.5
  %scevgep67 = getelementptr i8, ptr %scevgep66, i64 %39
  %.357.6 = load double, ptr %scevgep67, align 8
  %.361.6 = fadd double %.357.6, %acc.5.2.5
  %acc.5.2.6 = fmul double %arg.x, %.361.6
  %sunkaddr = mul i64 %.149171176, 8
  %sunkaddr24 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr
  %.465 = load double, ptr %sunkaddr24, align 8
  %.467 = fadd double %.465, %acc.5.2.6
  %41 = shl i64 %.149171176, 3
  %sunkaddr25 = mul i64 %.149171176, 8
  %sunkaddr26 = getelementptr i8, ptr %arg.out.4, i64 %sunkaddr25
  store double %.467, ptr %sunkaddr26, align 8
  %scevgep18 = getelementptr i8, ptr %scevgep54, i64 %41
  %scevgep19 = getelementptr i8, ptr %scevgep18, i64 -16
  %.357.127 = load double, ptr %scevgep19, align 8
  %.361.128 = fadd double %.357.127, 0.000000e+00
  %acc.5.2.129 = fmul double %arg.x, %.361.128
  %scevgep68 = getelementptr i8, ptr %scevgep62, i64 8
  %.357.1.1 = load double, ptr %scevgep68, align 8
  %.361.1.1 = fadd double %.357.1.1, %acc.5.2.129
  %acc.5.2.1.1 = fmul double %.423, %.361.1.1
  %scevgep69 = getelementptr i8, ptr %scevgep63, i64 8
  %.357.2.1 = load double, ptr %scevgep69, align 8
  %.361.2.1 = fadd double %.357.2.1, %acc.5.2.1.1
  %acc.5.2.2.1 = fmul double %arg.x, %.361.2.1
  %scevgep70 = getelementptr i8, ptr %scevgep64, i64 8
  %.357.3.1 = load double, ptr %scevgep70, align 8
  %.361.3.1 = fadd double %.357.3.1, %acc.5.2.2.1
  %acc.5.2.3.1 = fmul double %.423, %.361.3.1
  %scevgep71 = getelementptr i8, ptr %scevgep65, i64 8
  %.357.4.1 = load double, ptr %scevgep71, align 8
  %.361.4.1 = fadd double %.357.4.1, %acc.5.2.3.1
  %acc.5.2.4.1 = fmul double %arg.x, %.361.4.1
  %scevgep72 = getelementptr i8, ptr %scevgep66, i64 8
  %.357.5.1 = load double, ptr %scevgep72, align 8
  %.361.5.1 = fadd double %.357.5.1, %acc.5.2.4.1
  %acc.5.2.5.1 = fmul double %.423, %.361.5.1
  %scevgep73 = getelementptr i8, ptr %scevgep67, i64 8
  %.357.6.1 = load double, ptr %scevgep73, align 8
  %.361.6.1 = fadd double %.357.6.1, %acc.5.2.5.1
  %acc.5.2.6.1 = fmul double %arg.x, %.361.6.1
  %sunkaddr27 = mul i64 %.149171176, 8
  %sunkaddr28 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr27
  %sunkaddr29 = getelementptr i8, ptr %sunkaddr28, i64 8
  %.465.1 = load double, ptr %sunkaddr29, align 8
  %.467.1 = fadd double %.465.1, %acc.5.2.6.1
  %42 = shl i64 %.149171176, 3
  %sunkaddr30 = mul i64 %.149171176, 8
  %sunkaddr31 = getelementptr i8, ptr %arg.out.4, i64 %sunkaddr30
  %sunkaddr32 = getelementptr i8, ptr %sunkaddr31, i64 8
  store double %.467.1, ptr %sunkaddr32, align 8
  %scevgep16 = getelementptr i8, ptr %scevgep54, i64 %42
  %scevgep17 = getelementptr i8, ptr %scevgep16, i64 -8
  %.357.231 = load double, ptr %scevgep17, align 8
  %.361.232 = fadd double %.357.231, 0.000000e+00
  %acc.5.2.233 = fmul double %arg.x, %.361.232
  %scevgep74 = getelementptr i8, ptr %scevgep62, i64 16
  %.357.1.2 = load double, ptr %scevgep74, align 8
  %.361.1.2 = fadd double %.357.1.2, %acc.5.2.233
  %acc.5.2.1.2 = fmul double %.423, %.361.1.2
  %scevgep75 = getelementptr i8, ptr %scevgep63, i64 16
  %.357.2.2 = load double, ptr %scevgep75, align 8
  %.361.2.2 = fadd double %.357.2.2, %acc.5.2.1.2
  %acc.5.2.2.2 = fmul double %arg.x, %.361.2.2
  %scevgep76 = getelementptr i8, ptr %scevgep64, i64 16
  %.357.3.2 = load double, ptr %scevgep76, align 8
  %.361.3.2 = fadd double %.357.3.2, %acc.5.2.2.2
  %acc.5.2.3.2 = fmul double %.423, %.361.3.2
  %scevgep77 = getelementptr i8, ptr %scevgep65, i64 16
  %.357.4.2 = load double, ptr %scevgep77, align 8
  %.361.4.2 = fadd double %.357.4.2, %acc.5.2.3.2
  %acc.5.2.4.2 = fmul double %arg.x, %.361.4.2
  %scevgep78 = getelementptr i8, ptr %scevgep66, i64 16
  %.357.5.2 = load double, ptr %scevgep78, align 8
  %.361.5.2 = fadd double %.357.5.2, %acc.5.2.4.2
  %acc.5.2.5.2 = fmul double %.423, %.361.5.2
  %scevgep79 = getelementptr i8, ptr %scevgep67, i64 16
  %.357.6.2 = load double, ptr %scevgep79, align 8
  %.361.6.2 = fadd double %.357.6.2, %acc.5.2.5.2
  %acc.5.2.6.2 = fmul double %arg.x, %.361.6.2
  %sunkaddr33 = mul i64 %.149171176, 8
  %sunkaddr34 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr33
  %sunkaddr35 = getelementptr i8, ptr %sunkaddr34, i64 16
  %.465.2 = load double, ptr %sunkaddr35, align 8
  %.467.2 = fadd double %.465.2, %acc.5.2.6.2
  %sunkaddr36 = mul i64 %.149171176, 8
  %sunkaddr37 = getelementptr i8, ptr %arg.out.4, i64 %sunkaddr36
  %sunkaddr38 = getelementptr i8, ptr %sunkaddr37, i64 16
  store double %.467.2, ptr %sunkaddr38, align 8
  %.357.335 = load double, ptr %scevgep58, align 8
  %.361.336 = fadd double %.357.335, 0.000000e+00
  %acc.5.2.337 = fmul double %arg.x, %.361.336
  %scevgep80 = getelementptr i8, ptr %scevgep62, i64 24
  %.357.1.3 = load double, ptr %scevgep80, align 8
  %.361.1.3 = fadd double %.357.1.3, %acc.5.2.337
  %acc.5.2.1.3 = fmul double %.423, %.361.1.3
  %scevgep81 = getelementptr i8, ptr %scevgep63, i64 24
  %.357.2.3 = load double, ptr %scevgep81, align 8
  %.361.2.3 = fadd double %.357.2.3, %acc.5.2.1.3
  %acc.5.2.2.3 = fmul double %arg.x, %.361.2.3
  %scevgep82 = getelementptr i8, ptr %scevgep64, i64 24
  %.357.3.3 = load double, ptr %scevgep82, align 8
  %.361.3.3 = fadd double %.357.3.3, %acc.5.2.2.3
  %acc.5.2.3.3 = fmul double %.423, %.361.3.3
  %scevgep83 = getelementptr i8, ptr %scevgep65, i64 24
  %.357.4.3 = load double, ptr %scevgep83, align 8
  %.361.4.3 = fadd double %.357.4.3, %acc.5.2.3.3
  %acc.5.2.4.3 = fmul double %arg.x, %.361.4.3
  %scevgep84 = getelementptr i8, ptr %scevgep66, i64 24
  %.357.5.3 = load double, ptr %scevgep84, align 8
  %.361.5.3 = fadd double %.357.5.3, %acc.5.2.4.3
  %acc.5.2.5.3 = fmul double %.423, %.361.5.3
  %scevgep85 = getelementptr i8, ptr %scevgep67, i64 24
  %.357.6.3 = load double, ptr %scevgep85, align 8
  %.361.6.3 = fadd double %.357.6.3, %acc.5.2.5.3
  %acc.5.2.6.3 = fmul double %arg.x, %.361.6.3
  %.156.3 = add nuw nsw i64 %.149171176, 4
  %sunkaddr39 = mul i64 %.149171176, 8
  %sunkaddr40 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr39
  %sunkaddr41 = getelementptr i8, ptr %sunkaddr40, i64 24
  %.465.3 = load double, ptr %sunkaddr41, align 8
  %.467.3 = fadd double %.465.3, %acc.5.2.6.3
  %sunkaddr42 = mul i64 %.149171176, 8
  %sunkaddr43 = getelementptr i8, ptr %arg.out.4, i64 %sunkaddr42
  %sunkaddr44 = getelementptr i8, ptr %sunkaddr43, i64 24
  store double %.467.3, ptr %sunkaddr44, align 8
  %exitcond.not.3 = icmp eq i64 %arg.y.2, %.156.3
  br i1 %exitcond.not.3, label %B236, label %B50.endif.endif, !llvm.loop !165
}

define linkonce_odr noundef i32 @_ZN6charts7solvers4loop15_record_segmentB3v95B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedEdd5ArrayIdLi1E1C7mutable7alignedE5ArrayIdLi2E1C7mutable7alignedE5ArrayIdLi1E1C7mutable7alignedE5ArrayIxLi1E1C7mutable7alignedE(ptr noalias writeonly captures(none) %retptr, ptr noalias readnone captures(none) %excinfo, ptr %arg.row.0, ptr readnone captures(none) %arg.row.1, i64 %arg.row.2, i64 %arg.row.3, ptr writeonly captures(none) initializes((0, 16)) %arg.row.4, i64 %arg.row.5.0, i64 %arg.row.6.0, ptr %arg.irow.0, ptr readnone captures(none) %arg.irow.1, i64 %arg.irow.2, i64 %arg.irow.3, ptr writeonly captures(none) %arg.irow.4, i64 %arg.irow.5.0, i64 %arg.irow.6.0, double %arg.t, double %arg.h, ptr %arg.y.0, ptr readnone captures(none) %arg.y.1, i64 %arg.y.2, i64 %arg.y.3, ptr readonly captures(none) %arg.y.4, i64 %arg.y.5.0, i64 %arg.y.6.0, ptr %arg.F.0, ptr readnone captures(none) %arg.F.1, i64 %arg.F.2, i64 %arg.F.3, ptr readonly captures(none) %arg.F.4, i64 %arg.F.5.0, i64 %arg.F.5.1, i64 %arg.F.6.0, i64 %arg.F.6.1, ptr %arg.par.0, ptr readnone captures(none) %arg.par.1, i64 %arg.par.2, i64 %arg.par.3, ptr readonly captures(none) %arg.par.4, i64 %arg.par.5.0, i64 %arg.par.6.0, ptr %arg.ipar.0, ptr readnone captures(none) %arg.ipar.1, i64 %arg.ipar.2, i64 %arg.ipar.3, ptr readonly captures(none) %arg.ipar.4, i64 %arg.ipar.5.0, i64 %arg.ipar.6.0) local_unnamed_addr {
B0.endif:
  %const = bitcast i64 9223372036854775776 to i64
  tail call void @NRT_incref(ptr %arg.row.0)
  tail call void @NRT_incref(ptr %arg.irow.0)
  tail call void @NRT_incref(ptr %arg.y.0)
  tail call void @NRT_incref(ptr %arg.F.0)
  tail call void @NRT_incref(ptr %arg.par.0)
  tail call void @NRT_incref(ptr %arg.ipar.0)
  store double %arg.t, ptr %arg.row.4, align 8
  %.164 = getelementptr i8, ptr %arg.row.4, i64 8
  store double %arg.h, ptr %.164, align 8
  %.204 = icmp sgt i64 %arg.y.2, 0
  br i1 %.204, label %iter.check, label %B154.endif.preheader

iter.check:                                       ; preds = %B0.endif
  %min.iters.check = icmp samesign ult i64 %arg.y.2, 4
  br i1 %min.iters.check, label %B70.preheader, label %vector.memcheck

vector.memcheck:                                  ; preds = %iter.check
  %0 = ptrtoint ptr %arg.row.4 to i64
  %1 = ptrtoint ptr %arg.y.4 to i64
  %2 = add i64 %0, 16
  %3 = sub i64 %2, %1
  %diff.check = icmp ult i64 %3, 256
  br i1 %diff.check, label %B70.preheader, label %vector.main.loop.iter.check

vector.main.loop.iter.check:                      ; preds = %vector.memcheck
  %min.iters.check3 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check3, label %vec.epilog.ph, label %vector.ph

vector.ph:                                        ; preds = %vector.main.loop.iter.check
  %n.vec = and i64 %arg.y.2, %const
  br label %vector.body

vector.body:                                      ; preds = %vector.body, %vector.ph
  %index = phi i64 [ 0, %vector.ph ], [ %index.next, %vector.body ]
  %sunkaddr464 = mul i64 %index, 8
  %sunkaddr465 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr464
  %wide.load = load <8 x double>, ptr %sunkaddr465, align 8
  %sunkaddr466 = mul i64 %index, 8
  %sunkaddr467 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr466
  %sunkaddr468 = getelementptr i8, ptr %sunkaddr467, i64 64
  %wide.load4 = load <8 x double>, ptr %sunkaddr468, align 8
  %sunkaddr469 = mul i64 %index, 8
  %sunkaddr470 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr469
  %sunkaddr471 = getelementptr i8, ptr %sunkaddr470, i64 128
  %wide.load5 = load <8 x double>, ptr %sunkaddr471, align 8
  %sunkaddr = mul i64 %index, 8
  %sunkaddr472 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr
  %sunkaddr473 = getelementptr i8, ptr %sunkaddr472, i64 192
  %wide.load6 = load <8 x double>, ptr %sunkaddr473, align 8
  %sunkaddr474 = mul i64 %index, 8
  %sunkaddr475 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr474
  %sunkaddr476 = getelementptr i8, ptr %sunkaddr475, i64 16
  store <8 x double> %wide.load, ptr %sunkaddr476, align 8
  %sunkaddr477 = mul i64 %index, 8
  %sunkaddr478 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr477
  %sunkaddr479 = getelementptr i8, ptr %sunkaddr478, i64 80
  store <8 x double> %wide.load4, ptr %sunkaddr479, align 8
  %sunkaddr480 = mul i64 %index, 8
  %sunkaddr481 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr480
  %sunkaddr482 = getelementptr i8, ptr %sunkaddr481, i64 144
  store <8 x double> %wide.load5, ptr %sunkaddr482, align 8
  %sunkaddr483 = mul i64 %index, 8
  %sunkaddr484 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr483
  %sunkaddr485 = getelementptr i8, ptr %sunkaddr484, i64 208
  store <8 x double> %wide.load6, ptr %sunkaddr485, align 8
  %index.next = add nuw nsw i64 %index, 32
  %4 = icmp eq i64 %n.vec, %index.next
  br i1 %4, label %middle.block, label %vector.body, !llvm.loop !166

middle.block:                                     ; preds = %vector.body
  %cmp.n = icmp eq i64 %arg.y.2, %n.vec
  br i1 %cmp.n, label %iter.check19.thread, label %vec.epilog.iter.check

vec.epilog.iter.check:                            ; preds = %middle.block
  %5 = and i64 %arg.y.2, 28
  %min.epilog.iters.check = icmp eq i64 %5, 0
  br i1 %min.epilog.iters.check, label %B70.preheader, label %vec.epilog.ph, !prof !9

vec.epilog.ph:                                    ; preds = %vec.epilog.iter.check, %vector.main.loop.iter.check
  %vec.epilog.resume.val = phi i64 [ %n.vec, %vec.epilog.iter.check ], [ 0, %vector.main.loop.iter.check ]
  %const_mat455 = add i64 %const, 28
  %n.vec8 = and i64 %arg.y.2, %const_mat455
  br label %vec.epilog.vector.body

vec.epilog.vector.body:                           ; preds = %vec.epilog.vector.body, %vec.epilog.ph
  %index9 = phi i64 [ %vec.epilog.resume.val, %vec.epilog.ph ], [ %index.next11, %vec.epilog.vector.body ]
  %6 = shl i64 %index9, 3
  %scevgep930 = getelementptr i8, ptr %arg.y.4, i64 %6
  %wide.load10 = load <4 x double>, ptr %scevgep930, align 8
  %sunkaddr486 = mul i64 %index9, 8
  %sunkaddr487 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr486
  %sunkaddr488 = getelementptr i8, ptr %sunkaddr487, i64 16
  store <4 x double> %wide.load10, ptr %sunkaddr488, align 8
  %index.next11 = add nuw i64 %index9, 4
  %7 = icmp eq i64 %n.vec8, %index.next11
  br i1 %7, label %vec.epilog.middle.block, label %vec.epilog.vector.body, !llvm.loop !167

vec.epilog.middle.block:                          ; preds = %vec.epilog.vector.body
  %cmp.n12 = icmp eq i64 %arg.y.2, %n.vec8
  br i1 %cmp.n12, label %iter.check19.thread, label %B70.preheader

B70.preheader:                                    ; preds = %vec.epilog.middle.block, %vec.epilog.iter.check, %vector.memcheck, %iter.check
  %.254422424.ph = phi i64 [ 0, %iter.check ], [ 0, %vector.memcheck ], [ %n.vec, %vec.epilog.iter.check ], [ %n.vec8, %vec.epilog.middle.block ]
  %8 = sub nsw i64 %arg.y.2, %.254422424.ph
  %xtraiter = and i64 %8, 7
  %lcmp.mod.not = icmp eq i64 %xtraiter, 0
  br i1 %lcmp.mod.not, label %B70.prol.loopexit, label %B70.prol.preheader

B70.prol.preheader:                               ; preds = %B70.preheader
  br label %B70.prol

B70.prol:                                         ; preds = %B70.prol.preheader, %B70.prol
  %lsr.iv926 = phi i64 [ %lsr.iv.next927, %B70.prol ], [ %xtraiter, %B70.prol.preheader ]
  %.254422424.prol = phi i64 [ %.261.prol, %B70.prol ], [ %.254422424.ph, %B70.prol.preheader ]
  %.261.prol = add nuw i64 %.254422424.prol, 1
  %9 = shl i64 %.254422424.prol, 3
  %scevgep925 = getelementptr i8, ptr %arg.y.4, i64 %9
  %.315.prol = load double, ptr %scevgep925, align 8
  %sunkaddr489 = mul i64 %.254422424.prol, 8
  %sunkaddr490 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr489
  %sunkaddr491 = getelementptr i8, ptr %sunkaddr490, i64 16
  store double %.315.prol, ptr %sunkaddr491, align 8
  %lsr.iv.next927 = add nsw i64 %lsr.iv926, -1
  %prol.iter.cmp.not = icmp eq i64 %lsr.iv.next927, 0
  br i1 %prol.iter.cmp.not, label %B70.prol.loopexit, label %B70.prol, !llvm.loop !168

B70.prol.loopexit:                                ; preds = %B70.prol, %B70.preheader
  %.254422424.unr = phi i64 [ %.254422424.ph, %B70.preheader ], [ %.261.prol, %B70.prol ]
  %10 = sub nsw i64 %.254422424.ph, %arg.y.2
  %11 = icmp ugt i64 %10, -8
  br i1 %11, label %iter.check19, label %B70.preheader100

B70.preheader100:                                 ; preds = %B70.prol.loopexit
  br label %B70

B70:                                              ; preds = %B70.preheader100, %B70
  %.254422424 = phi i64 [ %.261.7, %B70 ], [ %.254422424.unr, %B70.preheader100 ]
  %sunkaddr492 = mul i64 %.254422424, 8
  %sunkaddr493 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr492
  %.315 = load double, ptr %sunkaddr493, align 8
  %sunkaddr494 = mul i64 %.254422424, 8
  %sunkaddr495 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr494
  %sunkaddr496 = getelementptr i8, ptr %sunkaddr495, i64 16
  store double %.315, ptr %sunkaddr496, align 8
  %sunkaddr497 = mul i64 %.254422424, 8
  %sunkaddr498 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr497
  %sunkaddr499 = getelementptr i8, ptr %sunkaddr498, i64 8
  %.315.1 = load double, ptr %sunkaddr499, align 8
  %sunkaddr500 = mul i64 %.254422424, 8
  %sunkaddr501 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr500
  %sunkaddr502 = getelementptr i8, ptr %sunkaddr501, i64 24
  store double %.315.1, ptr %sunkaddr502, align 8
  %sunkaddr503 = mul i64 %.254422424, 8
  %sunkaddr504 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr503
  %sunkaddr505 = getelementptr i8, ptr %sunkaddr504, i64 16
  %.315.2 = load double, ptr %sunkaddr505, align 8
  %sunkaddr506 = mul i64 %.254422424, 8
  %sunkaddr507 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr506
  %sunkaddr508 = getelementptr i8, ptr %sunkaddr507, i64 32
  store double %.315.2, ptr %sunkaddr508, align 8
  %sunkaddr509 = mul i64 %.254422424, 8
  %sunkaddr510 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr509
  %sunkaddr511 = getelementptr i8, ptr %sunkaddr510, i64 24
  %.315.3 = load double, ptr %sunkaddr511, align 8
  %sunkaddr512 = mul i64 %.254422424, 8
  %sunkaddr513 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr512
  %sunkaddr514 = getelementptr i8, ptr %sunkaddr513, i64 40
  store double %.315.3, ptr %sunkaddr514, align 8
  %sunkaddr515 = mul i64 %.254422424, 8
  %sunkaddr516 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr515
  %sunkaddr517 = getelementptr i8, ptr %sunkaddr516, i64 32
  %.315.4 = load double, ptr %sunkaddr517, align 8
  %sunkaddr518 = mul i64 %.254422424, 8
  %sunkaddr519 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr518
  %sunkaddr520 = getelementptr i8, ptr %sunkaddr519, i64 48
  store double %.315.4, ptr %sunkaddr520, align 8
  %sunkaddr521 = mul i64 %.254422424, 8
  %sunkaddr522 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr521
  %sunkaddr523 = getelementptr i8, ptr %sunkaddr522, i64 40
  %.315.5 = load double, ptr %sunkaddr523, align 8
  %sunkaddr524 = mul i64 %.254422424, 8
  %sunkaddr525 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr524
  %sunkaddr526 = getelementptr i8, ptr %sunkaddr525, i64 56
  store double %.315.5, ptr %sunkaddr526, align 8
  %sunkaddr527 = mul i64 %.254422424, 8
  %sunkaddr528 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr527
  %sunkaddr529 = getelementptr i8, ptr %sunkaddr528, i64 48
  %.315.6 = load double, ptr %sunkaddr529, align 8
  %sunkaddr530 = mul i64 %.254422424, 8
  %sunkaddr531 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr530
  %sunkaddr532 = getelementptr i8, ptr %sunkaddr531, i64 64
  store double %.315.6, ptr %sunkaddr532, align 8
  %.261.7 = add nuw nsw i64 %.254422424, 8
  %sunkaddr533 = mul i64 %.254422424, 8
  %sunkaddr534 = getelementptr i8, ptr %arg.y.4, i64 %sunkaddr533
  %sunkaddr535 = getelementptr i8, ptr %sunkaddr534, i64 56
  %.315.7 = load double, ptr %sunkaddr535, align 8
  %sunkaddr536 = mul i64 %.254422424, 8
  %sunkaddr537 = getelementptr i8, ptr %arg.row.4, i64 %sunkaddr536
  %sunkaddr538 = getelementptr i8, ptr %sunkaddr537, i64 72
  store double %.315.7, ptr %sunkaddr538, align 8
  %exitcond.not.7 = icmp eq i64 %arg.y.2, %.261.7
  br i1 %exitcond.not.7, label %iter.check19.thread, label %B70, !llvm.loop !169

B306:                                             ; preds = %B306.preheader396, %B306
  %.813446448 = phi i64 [ %.820.7, %B306 ], [ %.813446448.unr, %B306.preheader396 ]
  %sunkaddr539 = mul i64 %.813446448, 8
  %sunkaddr540 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr539
  %.874 = load double, ptr %sunkaddr540, align 8
  %12 = add i64 %369, %.813446448
  %13 = add i64 %12, 2
  %.890 = icmp slt i64 %13, 0
  %14 = select i1 %.890, i64 %370, i64 0
  %15 = add i64 %14, 16
  %scevgep162 = getelementptr i8, ptr %scevgep456, i64 %15
  %16 = shl i64 %.813446448, 3
  %scevgep163 = getelementptr i8, ptr %scevgep162, i64 %16
  store double %.874, ptr %scevgep163, align 8
  %sunkaddr541 = mul i64 %.813446448, 8
  %sunkaddr542 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr541
  %sunkaddr543 = getelementptr i8, ptr %sunkaddr542, i64 8
  %.874.1 = load double, ptr %sunkaddr543, align 8
  %17 = add i64 %369, %.813446448
  %18 = add i64 %17, 3
  %.890.1 = icmp slt i64 %18, 0
  %19 = select i1 %.890.1, i64 %370, i64 0
  %20 = add i64 %19, 24
  %scevgep160 = getelementptr i8, ptr %scevgep456, i64 %20
  %21 = shl i64 %.813446448, 3
  %scevgep161 = getelementptr i8, ptr %scevgep160, i64 %21
  store double %.874.1, ptr %scevgep161, align 8
  %sunkaddr544 = mul i64 %.813446448, 8
  %sunkaddr545 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr544
  %sunkaddr546 = getelementptr i8, ptr %sunkaddr545, i64 16
  %.874.2 = load double, ptr %sunkaddr546, align 8
  %22 = add i64 %369, %.813446448
  %23 = add i64 %22, 4
  %.890.2 = icmp slt i64 %23, 0
  %24 = select i1 %.890.2, i64 %370, i64 0
  %25 = add i64 %24, 32
  %scevgep158 = getelementptr i8, ptr %scevgep456, i64 %25
  %26 = shl i64 %.813446448, 3
  %scevgep159 = getelementptr i8, ptr %scevgep158, i64 %26
  store double %.874.2, ptr %scevgep159, align 8
  %sunkaddr547 = mul i64 %.813446448, 8
  %sunkaddr548 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr547
  %sunkaddr549 = getelementptr i8, ptr %sunkaddr548, i64 24
  %.874.3 = load double, ptr %sunkaddr549, align 8
  %27 = add i64 %369, %.813446448
  %28 = add i64 %27, 5
  %.890.3 = icmp slt i64 %28, 0
  %29 = select i1 %.890.3, i64 %370, i64 0
  %30 = add i64 %29, 40
  %scevgep156 = getelementptr i8, ptr %scevgep456, i64 %30
  %31 = shl i64 %.813446448, 3
  %scevgep157 = getelementptr i8, ptr %scevgep156, i64 %31
  store double %.874.3, ptr %scevgep157, align 8
  %sunkaddr550 = mul i64 %.813446448, 8
  %sunkaddr551 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr550
  %sunkaddr552 = getelementptr i8, ptr %sunkaddr551, i64 32
  %.874.4 = load double, ptr %sunkaddr552, align 8
  %32 = add i64 %369, %.813446448
  %33 = add i64 %32, 6
  %.890.4 = icmp slt i64 %33, 0
  %34 = select i1 %.890.4, i64 %370, i64 0
  %35 = add i64 %34, 48
  %scevgep154 = getelementptr i8, ptr %scevgep456, i64 %35
  %36 = shl i64 %.813446448, 3
  %scevgep155 = getelementptr i8, ptr %scevgep154, i64 %36
  store double %.874.4, ptr %scevgep155, align 8
  %sunkaddr553 = mul i64 %.813446448, 8
  %sunkaddr554 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr553
  %sunkaddr555 = getelementptr i8, ptr %sunkaddr554, i64 40
  %.874.5 = load double, ptr %sunkaddr555, align 8
  %37 = add i64 %369, %.813446448
  %38 = add i64 %37, 7
  %.890.5 = icmp slt i64 %38, 0
  %39 = select i1 %.890.5, i64 %370, i64 0
  %40 = add i64 %39, 56
  %scevgep152 = getelementptr i8, ptr %scevgep456, i64 %40
  %41 = shl i64 %.813446448, 3
  %scevgep153 = getelementptr i8, ptr %scevgep152, i64 %41
  store double %.874.5, ptr %scevgep153, align 8
  %sunkaddr556 = mul i64 %.813446448, 8
  %sunkaddr557 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr556
  %sunkaddr558 = getelementptr i8, ptr %sunkaddr557, i64 48
  %.874.6 = load double, ptr %sunkaddr558, align 8
  %42 = add i64 %369, %.813446448
  %43 = add i64 %42, 8
  %.890.6 = icmp slt i64 %43, 0
  %44 = select i1 %.890.6, i64 %370, i64 0
  %45 = add i64 %44, 64
  %scevgep150 = getelementptr i8, ptr %scevgep456, i64 %45
  %46 = shl i64 %.813446448, 3
  %scevgep151 = getelementptr i8, ptr %scevgep150, i64 %46
  store double %.874.6, ptr %scevgep151, align 8
  %.820.7 = add nuw nsw i64 %.813446448, 8
  %sunkaddr559 = mul i64 %.813446448, 8
  %sunkaddr560 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr559
  %sunkaddr561 = getelementptr i8, ptr %sunkaddr560, i64 56
  %.874.7 = load double, ptr %sunkaddr561, align 8
  %47 = add i64 %369, %.813446448
  %48 = add i64 %47, 9
  %.890.7 = icmp slt i64 %48, 0
  %49 = select i1 %.890.7, i64 %370, i64 0
  %50 = add i64 %49, 72
  %scevgep148 = getelementptr i8, ptr %scevgep456, i64 %50
  %51 = shl i64 %.813446448, 3
  %scevgep149 = getelementptr i8, ptr %scevgep148, i64 %51
  store double %.874.7, ptr %scevgep149, align 8
  %exitcond462.not.7 = icmp eq i64 %arg.par.2, %.820.7
  br i1 %exitcond462.not.7, label %B338.endif, label %B306, !llvm.loop !170

B380:                                             ; preds = %B380.preheader99, %B380
  %.1016453455 = phi i64 [ %.1023.7, %B380 ], [ %.1016453455.unr, %B380.preheader99 ]
  %sunkaddr562 = mul i64 %.1016453455, 8
  %sunkaddr563 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr562
  %.1077 = load i64, ptr %sunkaddr563, align 8
  %sunkaddr564 = mul i64 %.1016453455, 8
  %sunkaddr565 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr564
  store i64 %.1077, ptr %sunkaddr565, align 8
  %sunkaddr566 = mul i64 %.1016453455, 8
  %sunkaddr567 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr566
  %sunkaddr568 = getelementptr i8, ptr %sunkaddr567, i64 8
  %.1077.1 = load i64, ptr %sunkaddr568, align 8
  %sunkaddr569 = mul i64 %.1016453455, 8
  %sunkaddr570 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr569
  %sunkaddr571 = getelementptr i8, ptr %sunkaddr570, i64 8
  store i64 %.1077.1, ptr %sunkaddr571, align 8
  %sunkaddr572 = mul i64 %.1016453455, 8
  %sunkaddr573 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr572
  %sunkaddr574 = getelementptr i8, ptr %sunkaddr573, i64 16
  %.1077.2 = load i64, ptr %sunkaddr574, align 8
  %sunkaddr575 = mul i64 %.1016453455, 8
  %sunkaddr576 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr575
  %sunkaddr577 = getelementptr i8, ptr %sunkaddr576, i64 16
  store i64 %.1077.2, ptr %sunkaddr577, align 8
  %sunkaddr578 = mul i64 %.1016453455, 8
  %sunkaddr579 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr578
  %sunkaddr580 = getelementptr i8, ptr %sunkaddr579, i64 24
  %.1077.3 = load i64, ptr %sunkaddr580, align 8
  %sunkaddr581 = mul i64 %.1016453455, 8
  %sunkaddr582 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr581
  %sunkaddr583 = getelementptr i8, ptr %sunkaddr582, i64 24
  store i64 %.1077.3, ptr %sunkaddr583, align 8
  %sunkaddr584 = mul i64 %.1016453455, 8
  %sunkaddr585 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr584
  %sunkaddr586 = getelementptr i8, ptr %sunkaddr585, i64 32
  %.1077.4 = load i64, ptr %sunkaddr586, align 8
  %sunkaddr587 = mul i64 %.1016453455, 8
  %sunkaddr588 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr587
  %sunkaddr589 = getelementptr i8, ptr %sunkaddr588, i64 32
  store i64 %.1077.4, ptr %sunkaddr589, align 8
  %sunkaddr590 = mul i64 %.1016453455, 8
  %sunkaddr591 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr590
  %sunkaddr592 = getelementptr i8, ptr %sunkaddr591, i64 40
  %.1077.5 = load i64, ptr %sunkaddr592, align 8
  %sunkaddr593 = mul i64 %.1016453455, 8
  %sunkaddr594 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr593
  %sunkaddr595 = getelementptr i8, ptr %sunkaddr594, i64 40
  store i64 %.1077.5, ptr %sunkaddr595, align 8
  %sunkaddr596 = mul i64 %.1016453455, 8
  %sunkaddr597 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr596
  %sunkaddr598 = getelementptr i8, ptr %sunkaddr597, i64 48
  %.1077.6 = load i64, ptr %sunkaddr598, align 8
  %sunkaddr599 = mul i64 %.1016453455, 8
  %sunkaddr600 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr599
  %sunkaddr601 = getelementptr i8, ptr %sunkaddr600, i64 48
  store i64 %.1077.6, ptr %sunkaddr601, align 8
  %.1023.7 = add nuw nsw i64 %.1016453455, 8
  %sunkaddr602 = mul i64 %.1016453455, 8
  %sunkaddr603 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr602
  %sunkaddr604 = getelementptr i8, ptr %sunkaddr603, i64 56
  %.1077.7 = load i64, ptr %sunkaddr604, align 8
  %sunkaddr605 = mul i64 %.1016453455, 8
  %sunkaddr606 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr605
  %sunkaddr607 = getelementptr i8, ptr %sunkaddr606, i64 56
  store i64 %.1077.7, ptr %sunkaddr607, align 8
  %exitcond463.not.7 = icmp eq i64 %arg.ipar.2, %.1023.7
  br i1 %exitcond463.not.7, label %B406, label %B380, !llvm.loop !171

B406:                                             ; preds = %B380, %B380.prol.loopexit, %vec.epilog.middle.block336, %middle.block323, %B338.endif
  tail call void @NRT_decref(ptr %arg.irow.0)
  tail call void @NRT_decref(ptr %arg.ipar.0)
  store ptr null, ptr %retptr, align 8
  ret i32 0

iter.check19.thread:                              ; preds = %B70, %vec.epilog.middle.block, %middle.block
  tail call void @NRT_decref(ptr %arg.y.0)
  %.3581 = add nuw i64 %arg.y.2, 2
  %52 = getelementptr double, ptr %arg.row.4, i64 %.3581
  br label %vector.memcheck13

iter.check19:                                     ; preds = %B70.prol.loopexit
  %53 = icmp ult i64 %arg.y.2, 4
  tail call void @NRT_decref(ptr %arg.y.0)
  %.358 = add nuw i64 %arg.y.2, 2
  %54 = getelementptr double, ptr %arg.row.4, i64 %.358
  br i1 %53, label %B188.us.preheader, label %vector.memcheck13

vector.memcheck13:                                ; preds = %iter.check19.thread, %iter.check19
  %55 = phi ptr [ %52, %iter.check19.thread ], [ %54, %iter.check19 ]
  %.3585 = phi i64 [ %.3581, %iter.check19.thread ], [ %.358, %iter.check19 ]
  %56 = ptrtoint ptr %arg.row.4 to i64
  %57 = ptrtoint ptr %arg.F.4 to i64
  %58 = shl i64 %arg.y.2, 3
  %59 = add i64 %56, 16
  %60 = add i64 %59, %58
  %61 = sub i64 %60, %57
  %diff.check16 = icmp ult i64 %61, 256
  br i1 %diff.check16, label %B188.us.preheader, label %vector.main.loop.iter.check21

vector.main.loop.iter.check21:                    ; preds = %vector.memcheck13
  %min.iters.check20 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check20, label %vec.epilog.ph38, label %vector.ph22

vector.ph22:                                      ; preds = %vector.main.loop.iter.check21
  %n.vec24 = and i64 %arg.y.2, %const
  %62 = getelementptr i8, ptr %arg.row.4, i64 %58
  %scevgep875 = getelementptr i8, ptr %62, i64 208
  br label %vector.body25

vector.body25:                                    ; preds = %vector.body25, %vector.ph22
  %index26 = phi i64 [ 0, %vector.ph22 ], [ %index.next31, %vector.body25 ]
  %sunkaddr608 = mul i64 %index26, 8
  %sunkaddr609 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr608
  %wide.load27 = load <8 x double>, ptr %sunkaddr609, align 8
  %sunkaddr610 = mul i64 %index26, 8
  %sunkaddr611 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr610
  %sunkaddr612 = getelementptr i8, ptr %sunkaddr611, i64 64
  %wide.load28 = load <8 x double>, ptr %sunkaddr612, align 8
  %sunkaddr613 = mul i64 %index26, 8
  %sunkaddr614 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr613
  %sunkaddr615 = getelementptr i8, ptr %sunkaddr614, i64 128
  %wide.load29 = load <8 x double>, ptr %sunkaddr615, align 8
  %sunkaddr616 = mul i64 %index26, 8
  %sunkaddr617 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr616
  %sunkaddr618 = getelementptr i8, ptr %sunkaddr617, i64 192
  %wide.load30 = load <8 x double>, ptr %sunkaddr618, align 8
  %63 = shl i64 %index26, 3
  %scevgep387 = getelementptr i8, ptr %scevgep875, i64 %63
  %scevgep390 = getelementptr i8, ptr %scevgep387, i64 -192
  %scevgep389 = getelementptr i8, ptr %scevgep387, i64 -128
  %scevgep388 = getelementptr i8, ptr %scevgep387, i64 -64
  store <8 x double> %wide.load27, ptr %scevgep390, align 8
  store <8 x double> %wide.load28, ptr %scevgep389, align 8
  store <8 x double> %wide.load29, ptr %scevgep388, align 8
  store <8 x double> %wide.load30, ptr %scevgep387, align 8
  %index.next31 = add nuw i64 %index26, 32
  %64 = icmp eq i64 %n.vec24, %index.next31
  br i1 %64, label %middle.block32, label %vector.body25, !llvm.loop !172

middle.block32:                                   ; preds = %vector.body25
  %cmp.n33 = icmp eq i64 %arg.y.2, %n.vec24
  br i1 %cmp.n33, label %iter.check54.thread, label %vec.epilog.iter.check36

vec.epilog.iter.check36:                          ; preds = %middle.block32
  %65 = and i64 %arg.y.2, 28
  %min.epilog.iters.check37 = icmp eq i64 %65, 0
  br i1 %min.epilog.iters.check37, label %B188.us.preheader, label %vec.epilog.ph38, !prof !9

vec.epilog.ph38:                                  ; preds = %vec.epilog.iter.check36, %vector.main.loop.iter.check21
  %vec.epilog.resume.val34 = phi i64 [ %n.vec24, %vec.epilog.iter.check36 ], [ 0, %vector.main.loop.iter.check21 ]
  %const_mat456 = add i64 %const, 28
  %n.vec40 = and i64 %arg.y.2, %const_mat456
  br label %vec.epilog.vector.body41

vec.epilog.vector.body41:                         ; preds = %vec.epilog.vector.body41, %vec.epilog.ph38
  %index42 = phi i64 [ %vec.epilog.resume.val34, %vec.epilog.ph38 ], [ %index.next44, %vec.epilog.vector.body41 ]
  %66 = shl i64 %index42, 3
  %scevgep874 = getelementptr i8, ptr %arg.F.4, i64 %66
  %wide.load43 = load <4 x double>, ptr %scevgep874, align 8
  %scevgep873 = getelementptr i8, ptr %55, i64 %66
  store <4 x double> %wide.load43, ptr %scevgep873, align 8
  %index.next44 = add nuw i64 %index42, 4
  %67 = icmp eq i64 %n.vec40, %index.next44
  br i1 %67, label %vec.epilog.middle.block45, label %vec.epilog.vector.body41, !llvm.loop !173

vec.epilog.middle.block45:                        ; preds = %vec.epilog.vector.body41
  %cmp.n46 = icmp eq i64 %arg.y.2, %n.vec40
  br i1 %cmp.n46, label %iter.check54.thread, label %B188.us.preheader

B188.us.preheader:                                ; preds = %vec.epilog.middle.block45, %vec.epilog.iter.check36, %vector.memcheck13, %iter.check19
  %68 = phi ptr [ %54, %iter.check19 ], [ %55, %vec.epilog.iter.check36 ], [ %55, %vector.memcheck13 ], [ %55, %vec.epilog.middle.block45 ]
  %.3584 = phi i64 [ %.358, %iter.check19 ], [ %.3585, %vec.epilog.iter.check36 ], [ %.3585, %vector.memcheck13 ], [ %.3585, %vec.epilog.middle.block45 ]
  %.568428430.us.ph = phi i64 [ 0, %iter.check19 ], [ %n.vec24, %vec.epilog.iter.check36 ], [ 0, %vector.memcheck13 ], [ %n.vec40, %vec.epilog.middle.block45 ]
  %69 = sub nsw i64 %arg.y.2, %.568428430.us.ph
  %xtraiter340 = and i64 %69, 7
  %lcmp.mod341.not = icmp eq i64 %xtraiter340, 0
  br i1 %lcmp.mod341.not, label %B188.us.prol.loopexit, label %B188.us.prol.preheader

B188.us.prol.preheader:                           ; preds = %B188.us.preheader
  br label %B188.us.prol

B188.us.prol:                                     ; preds = %B188.us.prol.preheader, %B188.us.prol
  %lsr.iv871 = phi i64 [ %lsr.iv.next872, %B188.us.prol ], [ %xtraiter340, %B188.us.prol.preheader ]
  %.568428430.us.prol = phi i64 [ %.575.us.prol, %B188.us.prol ], [ %.568428430.us.ph, %B188.us.prol.preheader ]
  %.575.us.prol = add nuw i64 %.568428430.us.prol, 1
  %70 = shl i64 %.568428430.us.prol, 3
  %scevgep870 = getelementptr i8, ptr %arg.F.4, i64 %70
  %.652.us.prol = load double, ptr %scevgep870, align 8
  %scevgep869 = getelementptr i8, ptr %68, i64 %70
  store double %.652.us.prol, ptr %scevgep869, align 8
  %lsr.iv.next872 = add nsw i64 %lsr.iv871, -1
  %prol.iter342.cmp.not = icmp eq i64 %lsr.iv.next872, 0
  br i1 %prol.iter342.cmp.not, label %B188.us.prol.loopexit, label %B188.us.prol, !llvm.loop !174

B188.us.prol.loopexit:                            ; preds = %B188.us.prol, %B188.us.preheader
  %.568428430.us.unr = phi i64 [ %.568428430.us.ph, %B188.us.preheader ], [ %.575.us.prol, %B188.us.prol ]
  %71 = sub nsw i64 %.568428430.us.ph, %arg.y.2
  %72 = icmp ugt i64 %71, -8
  br i1 %72, label %iter.check54, label %B188.us.preheader403

B188.us.preheader403:                             ; preds = %B188.us.prol.loopexit
  %73 = shl i64 %arg.y.2, 3
  %74 = getelementptr i8, ptr %arg.row.4, i64 %73
  %scevgep837 = getelementptr i8, ptr %74, i64 72
  br label %B188.us

B154.endif.preheader:                             ; preds = %B0.endif
  tail call void @NRT_decref(ptr %arg.y.0)
  %.358473 = add nsw i64 %arg.y.2, 2
  br label %B238.endif

B188.us:                                          ; preds = %B188.us, %B188.us.preheader403
  %.568428430.us = phi i64 [ %.575.us.7, %B188.us ], [ %.568428430.us.unr, %B188.us.preheader403 ]
  %sunkaddr1111 = shl i64 %.568428430.us, 3
  %sunkaddr619 = mul i64 %.568428430.us, 8
  %sunkaddr620 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr619
  %.652.us = load double, ptr %sunkaddr620, align 8
  %scevgep849 = getelementptr i8, ptr %scevgep837, i64 %sunkaddr1111
  %scevgep850 = getelementptr i8, ptr %scevgep849, i64 -56
  store double %.652.us, ptr %scevgep850, align 8
  %sunkaddr621 = mul i64 %.568428430.us, 8
  %sunkaddr622 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr621
  %sunkaddr623 = getelementptr i8, ptr %sunkaddr622, i64 8
  %.652.us.1345 = load double, ptr %sunkaddr623, align 8
  %75 = shl i64 %.568428430.us, 3
  %scevgep369 = getelementptr i8, ptr %scevgep837, i64 %75
  %scevgep370 = getelementptr i8, ptr %scevgep369, i64 -48
  store double %.652.us.1345, ptr %scevgep370, align 8
  %sunkaddr624 = mul i64 %.568428430.us, 8
  %sunkaddr625 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr624
  %sunkaddr626 = getelementptr i8, ptr %sunkaddr625, i64 16
  %.652.us.2349 = load double, ptr %sunkaddr626, align 8
  %76 = shl i64 %.568428430.us, 3
  %scevgep367 = getelementptr i8, ptr %scevgep837, i64 %76
  %scevgep368 = getelementptr i8, ptr %scevgep367, i64 -40
  store double %.652.us.2349, ptr %scevgep368, align 8
  %sunkaddr627 = mul i64 %.568428430.us, 8
  %sunkaddr628 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr627
  %sunkaddr629 = getelementptr i8, ptr %sunkaddr628, i64 24
  %.652.us.3353 = load double, ptr %sunkaddr629, align 8
  %77 = shl i64 %.568428430.us, 3
  %scevgep365 = getelementptr i8, ptr %scevgep837, i64 %77
  %scevgep366 = getelementptr i8, ptr %scevgep365, i64 -32
  store double %.652.us.3353, ptr %scevgep366, align 8
  %sunkaddr630 = mul i64 %.568428430.us, 8
  %sunkaddr631 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr630
  %sunkaddr632 = getelementptr i8, ptr %sunkaddr631, i64 32
  %.652.us.4357 = load double, ptr %sunkaddr632, align 8
  %78 = shl i64 %.568428430.us, 3
  %scevgep363 = getelementptr i8, ptr %scevgep837, i64 %78
  %scevgep364 = getelementptr i8, ptr %scevgep363, i64 -24
  store double %.652.us.4357, ptr %scevgep364, align 8
  %sunkaddr633 = mul i64 %.568428430.us, 8
  %sunkaddr634 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr633
  %sunkaddr635 = getelementptr i8, ptr %sunkaddr634, i64 40
  %.652.us.5361 = load double, ptr %sunkaddr635, align 8
  %79 = shl i64 %.568428430.us, 3
  %scevgep361 = getelementptr i8, ptr %scevgep837, i64 %79
  %scevgep362 = getelementptr i8, ptr %scevgep361, i64 -16
  store double %.652.us.5361, ptr %scevgep362, align 8
  %sunkaddr636 = mul i64 %.568428430.us, 8
  %sunkaddr637 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr636
  %sunkaddr638 = getelementptr i8, ptr %sunkaddr637, i64 48
  %.652.us.6365 = load double, ptr %sunkaddr638, align 8
  %80 = shl i64 %.568428430.us, 3
  %scevgep359 = getelementptr i8, ptr %scevgep837, i64 %80
  %scevgep360 = getelementptr i8, ptr %scevgep359, i64 -8
  store double %.652.us.6365, ptr %scevgep360, align 8
  %.575.us.7 = add nuw nsw i64 %.568428430.us, 8
  %sunkaddr639 = mul i64 %.568428430.us, 8
  %sunkaddr640 = getelementptr i8, ptr %arg.F.4, i64 %sunkaddr639
  %sunkaddr641 = getelementptr i8, ptr %sunkaddr640, i64 56
  %.652.us.7 = load double, ptr %sunkaddr641, align 8
  store double %.652.us.7, ptr %scevgep849, align 8
  %exitcond460.not.7 = icmp eq i64 %arg.y.2, %.575.us.7
  br i1 %exitcond460.not.7, label %iter.check54.thread, label %B188.us, !llvm.loop !175

iter.check54.thread:                              ; preds = %B188.us, %vec.epilog.middle.block45, %middle.block32
  %.3583.ph = phi i64 [ %.3585, %middle.block32 ], [ %.3585, %vec.epilog.middle.block45 ], [ %.3584, %B188.us ]
  %81 = getelementptr double, ptr %arg.F.4, i64 %arg.F.5.1
  %82 = getelementptr double, ptr %arg.row.4, i64 %arg.y.2
  %83 = getelementptr double, ptr %82, i64 %.3583.ph
  br label %vector.memcheck48

iter.check54:                                     ; preds = %B188.us.prol.loopexit
  %84 = icmp ult i64 %arg.y.2, 4
  %85 = getelementptr double, ptr %arg.F.4, i64 %arg.F.5.1
  %86 = getelementptr double, ptr %arg.row.4, i64 %arg.y.2
  %87 = getelementptr double, ptr %86, i64 %.3584
  br i1 %84, label %B188.us.1.preheader, label %vector.memcheck48

vector.memcheck48:                                ; preds = %iter.check54.thread, %iter.check54
  %88 = phi ptr [ %83, %iter.check54.thread ], [ %87, %iter.check54 ]
  %89 = phi ptr [ %81, %iter.check54.thread ], [ %85, %iter.check54 ]
  %.358310 = phi i64 [ %.3583.ph, %iter.check54.thread ], [ %.3584, %iter.check54 ]
  %90 = ptrtoint ptr %arg.row.4 to i64
  %91 = ptrtoint ptr %arg.F.4 to i64
  %92 = shl i64 %arg.y.2, 4
  %93 = shl i64 %arg.F.5.1, 3
  %.neg58 = add i64 %90, 16
  %94 = add i64 %.neg58, %92
  %95 = add i64 %93, %91
  %96 = sub i64 %94, %95
  %diff.check51 = icmp ult i64 %96, 256
  br i1 %diff.check51, label %B188.us.1.preheader, label %vector.main.loop.iter.check56

vector.main.loop.iter.check56:                    ; preds = %vector.memcheck48
  %min.iters.check55 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check55, label %vec.epilog.ph73, label %vector.ph57

vector.ph57:                                      ; preds = %vector.main.loop.iter.check56
  %n.vec59 = and i64 %arg.y.2, %const
  %97 = getelementptr i8, ptr %arg.row.4, i64 %92
  %scevgep821 = getelementptr i8, ptr %97, i64 208
  %98 = getelementptr i8, ptr %arg.F.4, i64 %93
  %scevgep829 = getelementptr i8, ptr %98, i64 192
  br label %vector.body60

vector.body60:                                    ; preds = %vector.body60, %vector.ph57
  %index61 = phi i64 [ 0, %vector.ph57 ], [ %index.next66, %vector.body60 ]
  %99 = shl i64 %index61, 3
  %scevgep835 = getelementptr i8, ptr %scevgep829, i64 %99
  %scevgep836 = getelementptr i8, ptr %scevgep835, i64 -192
  %scevgep834 = getelementptr i8, ptr %scevgep835, i64 -128
  %scevgep832 = getelementptr i8, ptr %scevgep835, i64 -64
  %wide.load62 = load <8 x double>, ptr %scevgep836, align 8
  %wide.load63 = load <8 x double>, ptr %scevgep834, align 8
  %wide.load64 = load <8 x double>, ptr %scevgep832, align 8
  %wide.load65 = load <8 x double>, ptr %scevgep835, align 8
  %100 = shl i64 %index61, 3
  %scevgep355 = getelementptr i8, ptr %scevgep821, i64 %100
  %scevgep358 = getelementptr i8, ptr %scevgep355, i64 -192
  %scevgep357 = getelementptr i8, ptr %scevgep355, i64 -128
  %scevgep356 = getelementptr i8, ptr %scevgep355, i64 -64
  store <8 x double> %wide.load62, ptr %scevgep358, align 8
  store <8 x double> %wide.load63, ptr %scevgep357, align 8
  store <8 x double> %wide.load64, ptr %scevgep356, align 8
  store <8 x double> %wide.load65, ptr %scevgep355, align 8
  %index.next66 = add nuw i64 %index61, 32
  %101 = icmp eq i64 %n.vec59, %index.next66
  br i1 %101, label %middle.block67, label %vector.body60, !llvm.loop !176

middle.block67:                                   ; preds = %vector.body60
  %cmp.n68 = icmp eq i64 %arg.y.2, %n.vec59
  br i1 %cmp.n68, label %iter.check89.thread, label %vec.epilog.iter.check71

vec.epilog.iter.check71:                          ; preds = %middle.block67
  %102 = and i64 %arg.y.2, 28
  %min.epilog.iters.check72 = icmp eq i64 %102, 0
  br i1 %min.epilog.iters.check72, label %B188.us.1.preheader, label %vec.epilog.ph73, !prof !9

vec.epilog.ph73:                                  ; preds = %vec.epilog.iter.check71, %vector.main.loop.iter.check56
  %vec.epilog.resume.val69 = phi i64 [ %n.vec59, %vec.epilog.iter.check71 ], [ 0, %vector.main.loop.iter.check56 ]
  %const_mat457 = add i64 %const, 28
  %n.vec75 = and i64 %arg.y.2, %const_mat457
  %103 = getelementptr double, ptr %arg.F.4, i64 %arg.F.5.1
  br label %vec.epilog.vector.body76

vec.epilog.vector.body76:                         ; preds = %vec.epilog.vector.body76, %vec.epilog.ph73
  %index77 = phi i64 [ %vec.epilog.resume.val69, %vec.epilog.ph73 ], [ %index.next79, %vec.epilog.vector.body76 ]
  %104 = shl i64 %index77, 3
  %scevgep820 = getelementptr i8, ptr %103, i64 %104
  %wide.load78 = load <4 x double>, ptr %scevgep820, align 8
  %scevgep819 = getelementptr i8, ptr %88, i64 %104
  store <4 x double> %wide.load78, ptr %scevgep819, align 8
  %index.next79 = add nuw i64 %index77, 4
  %105 = icmp eq i64 %n.vec75, %index.next79
  br i1 %105, label %vec.epilog.middle.block80, label %vec.epilog.vector.body76, !llvm.loop !177

vec.epilog.middle.block80:                        ; preds = %vec.epilog.vector.body76
  %cmp.n81 = icmp eq i64 %arg.y.2, %n.vec75
  br i1 %cmp.n81, label %iter.check89.thread, label %B188.us.1.preheader

B188.us.1.preheader:                              ; preds = %vec.epilog.middle.block80, %vec.epilog.iter.check71, %vector.memcheck48, %iter.check54
  %106 = phi ptr [ %87, %iter.check54 ], [ %88, %vec.epilog.iter.check71 ], [ %88, %vector.memcheck48 ], [ %88, %vec.epilog.middle.block80 ]
  %107 = phi ptr [ %85, %iter.check54 ], [ %89, %vec.epilog.iter.check71 ], [ %89, %vector.memcheck48 ], [ %89, %vec.epilog.middle.block80 ]
  %.35839 = phi i64 [ %.3584, %iter.check54 ], [ %.358310, %vec.epilog.iter.check71 ], [ %.358310, %vector.memcheck48 ], [ %.358310, %vec.epilog.middle.block80 ]
  %.568428430.us.1.ph = phi i64 [ 0, %iter.check54 ], [ %n.vec59, %vec.epilog.iter.check71 ], [ 0, %vector.memcheck48 ], [ %n.vec75, %vec.epilog.middle.block80 ]
  %108 = sub nsw i64 %arg.y.2, %.568428430.us.1.ph
  %xtraiter367 = and i64 %108, 7
  %lcmp.mod368.not = icmp eq i64 %xtraiter367, 0
  br i1 %lcmp.mod368.not, label %B188.us.1.prol.loopexit, label %B188.us.1.prol.preheader

B188.us.1.prol.preheader:                         ; preds = %B188.us.1.preheader
  br label %B188.us.1.prol

B188.us.1.prol:                                   ; preds = %B188.us.1.prol.preheader, %B188.us.1.prol
  %lsr.iv817 = phi i64 [ %lsr.iv.next818, %B188.us.1.prol ], [ %xtraiter367, %B188.us.1.prol.preheader ]
  %.568428430.us.1.prol = phi i64 [ %.575.us.1.prol, %B188.us.1.prol ], [ %.568428430.us.1.ph, %B188.us.1.prol.preheader ]
  %.575.us.1.prol = add nuw i64 %.568428430.us.1.prol, 1
  %109 = shl i64 %.568428430.us.1.prol, 3
  %scevgep816 = getelementptr i8, ptr %107, i64 %109
  %.652.us.1.prol = load double, ptr %scevgep816, align 8
  %scevgep815 = getelementptr i8, ptr %106, i64 %109
  store double %.652.us.1.prol, ptr %scevgep815, align 8
  %lsr.iv.next818 = add nsw i64 %lsr.iv817, -1
  %prol.iter369.cmp.not = icmp eq i64 %lsr.iv.next818, 0
  br i1 %prol.iter369.cmp.not, label %B188.us.1.prol.loopexit, label %B188.us.1.prol, !llvm.loop !178

B188.us.1.prol.loopexit:                          ; preds = %B188.us.1.prol, %B188.us.1.preheader
  %.568428430.us.1.unr = phi i64 [ %.568428430.us.1.ph, %B188.us.1.preheader ], [ %.575.us.1.prol, %B188.us.1.prol ]
  %110 = sub nsw i64 %.568428430.us.1.ph, %arg.y.2
  %111 = icmp ugt i64 %110, -8
  br i1 %111, label %iter.check89, label %B188.us.1.preheader402

B188.us.1.preheader402:                           ; preds = %B188.us.1.prol.loopexit
  %112 = shl i64 %arg.y.2, 4
  %113 = getelementptr i8, ptr %arg.row.4, i64 %112
  %scevgep783 = getelementptr i8, ptr %113, i64 72
  %114 = shl i64 %arg.F.5.1, 3
  %115 = getelementptr i8, ptr %arg.F.4, i64 %114
  %scevgep799 = getelementptr i8, ptr %115, i64 56
  br label %B188.us.1

B188.us.1:                                        ; preds = %B188.us.1, %B188.us.1.preheader402
  %.568428430.us.1 = phi i64 [ %.575.us.1.7, %B188.us.1 ], [ %.568428430.us.1.unr, %B188.us.1.preheader402 ]
  %116 = shl i64 %.568428430.us.1, 3
  %scevgep811 = getelementptr i8, ptr %scevgep799, i64 %116
  %scevgep812 = getelementptr i8, ptr %scevgep811, i64 -56
  %.652.us.1 = load double, ptr %scevgep812, align 8
  %scevgep795 = getelementptr i8, ptr %scevgep783, i64 %116
  %scevgep796 = getelementptr i8, ptr %scevgep795, i64 -56
  store double %.652.us.1, ptr %scevgep796, align 8
  %117 = shl i64 %.568428430.us.1, 3
  %scevgep353 = getelementptr i8, ptr %scevgep799, i64 %117
  %scevgep354 = getelementptr i8, ptr %scevgep353, i64 -48
  %.652.us.1.1 = load double, ptr %scevgep354, align 8
  %118 = shl i64 %.568428430.us.1, 3
  %scevgep341 = getelementptr i8, ptr %scevgep783, i64 %118
  %scevgep342 = getelementptr i8, ptr %scevgep341, i64 -48
  store double %.652.us.1.1, ptr %scevgep342, align 8
  %scevgep351 = getelementptr i8, ptr %scevgep799, i64 %118
  %scevgep352 = getelementptr i8, ptr %scevgep351, i64 -40
  %.652.us.1.2 = load double, ptr %scevgep352, align 8
  %119 = shl i64 %.568428430.us.1, 3
  %scevgep339 = getelementptr i8, ptr %scevgep783, i64 %119
  %scevgep340 = getelementptr i8, ptr %scevgep339, i64 -40
  store double %.652.us.1.2, ptr %scevgep340, align 8
  %scevgep349 = getelementptr i8, ptr %scevgep799, i64 %119
  %scevgep350 = getelementptr i8, ptr %scevgep349, i64 -32
  %.652.us.1.3 = load double, ptr %scevgep350, align 8
  %120 = shl i64 %.568428430.us.1, 3
  %scevgep337 = getelementptr i8, ptr %scevgep783, i64 %120
  %scevgep338 = getelementptr i8, ptr %scevgep337, i64 -32
  store double %.652.us.1.3, ptr %scevgep338, align 8
  %scevgep347 = getelementptr i8, ptr %scevgep799, i64 %120
  %scevgep348 = getelementptr i8, ptr %scevgep347, i64 -24
  %.652.us.1.4 = load double, ptr %scevgep348, align 8
  %121 = shl i64 %.568428430.us.1, 3
  %scevgep335 = getelementptr i8, ptr %scevgep783, i64 %121
  %scevgep336 = getelementptr i8, ptr %scevgep335, i64 -24
  store double %.652.us.1.4, ptr %scevgep336, align 8
  %scevgep345 = getelementptr i8, ptr %scevgep799, i64 %121
  %scevgep346 = getelementptr i8, ptr %scevgep345, i64 -16
  %.652.us.1.5 = load double, ptr %scevgep346, align 8
  %122 = shl i64 %.568428430.us.1, 3
  %scevgep333 = getelementptr i8, ptr %scevgep783, i64 %122
  %scevgep334 = getelementptr i8, ptr %scevgep333, i64 -16
  store double %.652.us.1.5, ptr %scevgep334, align 8
  %scevgep343 = getelementptr i8, ptr %scevgep799, i64 %122
  %scevgep344 = getelementptr i8, ptr %scevgep343, i64 -8
  %.652.us.1.6 = load double, ptr %scevgep344, align 8
  %123 = shl i64 %.568428430.us.1, 3
  %scevgep331 = getelementptr i8, ptr %scevgep783, i64 %123
  %scevgep332 = getelementptr i8, ptr %scevgep331, i64 -8
  store double %.652.us.1.6, ptr %scevgep332, align 8
  %.575.us.1.7 = add nuw nsw i64 %.568428430.us.1, 8
  %.652.us.1.7 = load double, ptr %scevgep811, align 8
  store double %.652.us.1.7, ptr %scevgep795, align 8
  %exitcond460.1.not.7 = icmp eq i64 %arg.y.2, %.575.us.1.7
  br i1 %exitcond460.1.not.7, label %iter.check89.thread, label %B188.us.1, !llvm.loop !179

iter.check89.thread:                              ; preds = %B188.us.1, %vec.epilog.middle.block80, %middle.block67
  %.idx46413.pre-phi = phi i64 [ %92, %middle.block67 ], [ %92, %vec.epilog.middle.block80 ], [ %112, %B188.us.1 ]
  %.35838.ph = phi i64 [ %.358310, %middle.block67 ], [ %.358310, %vec.epilog.middle.block80 ], [ %.35839, %B188.us.1 ]
  %.idx12 = shl i64 %arg.F.5.1, 4
  %124 = getelementptr i8, ptr %arg.F.4, i64 %.idx12
  %125 = getelementptr i8, ptr %arg.row.4, i64 %.idx46413.pre-phi
  %126 = getelementptr double, ptr %125, i64 %.35838.ph
  br label %vector.memcheck83

iter.check89:                                     ; preds = %B188.us.1.prol.loopexit
  %127 = icmp ult i64 %arg.y.2, 4
  %.idx = shl i64 %arg.F.5.1, 4
  %128 = getelementptr i8, ptr %arg.F.4, i64 %.idx
  %.idx464 = shl i64 %arg.y.2, 4
  %129 = getelementptr i8, ptr %arg.row.4, i64 %.idx464
  %130 = getelementptr double, ptr %129, i64 %.35839
  br i1 %127, label %B188.us.2.preheader, label %vector.memcheck83

vector.memcheck83:                                ; preds = %iter.check89.thread, %iter.check89
  %131 = phi ptr [ %126, %iter.check89.thread ], [ %130, %iter.check89 ]
  %132 = phi ptr [ %124, %iter.check89.thread ], [ %128, %iter.check89 ]
  %.idx18 = phi i64 [ %.idx12, %iter.check89.thread ], [ %.idx, %iter.check89 ]
  %.3583817 = phi i64 [ %.35838.ph, %iter.check89.thread ], [ %.35839, %iter.check89 ]
  %133 = ptrtoint ptr %arg.row.4 to i64
  %134 = ptrtoint ptr %arg.F.4 to i64
  %135 = mul i64 %arg.y.2, 24
  %.neg60 = add i64 %133, 16
  %136 = add i64 %.neg60, %135
  %137 = add i64 %.idx18, %134
  %138 = sub i64 %136, %137
  %diff.check86 = icmp ult i64 %138, 256
  br i1 %diff.check86, label %B188.us.2.preheader, label %vector.main.loop.iter.check91

vector.main.loop.iter.check91:                    ; preds = %vector.memcheck83
  %min.iters.check90 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check90, label %vec.epilog.ph108, label %vector.ph92

vector.ph92:                                      ; preds = %vector.main.loop.iter.check91
  %n.vec94 = and i64 %arg.y.2, %const
  %139 = getelementptr i8, ptr %arg.row.4, i64 %135
  %scevgep767 = getelementptr i8, ptr %139, i64 208
  %140 = getelementptr i8, ptr %arg.F.4, i64 %.idx18
  %scevgep775 = getelementptr i8, ptr %140, i64 192
  br label %vector.body95

vector.body95:                                    ; preds = %vector.body95, %vector.ph92
  %index96 = phi i64 [ 0, %vector.ph92 ], [ %index.next101, %vector.body95 ]
  %141 = shl i64 %index96, 3
  %scevgep781 = getelementptr i8, ptr %scevgep775, i64 %141
  %scevgep782 = getelementptr i8, ptr %scevgep781, i64 -192
  %scevgep780 = getelementptr i8, ptr %scevgep781, i64 -128
  %scevgep778 = getelementptr i8, ptr %scevgep781, i64 -64
  %wide.load97 = load <8 x double>, ptr %scevgep782, align 8
  %wide.load98 = load <8 x double>, ptr %scevgep780, align 8
  %wide.load99 = load <8 x double>, ptr %scevgep778, align 8
  %wide.load100 = load <8 x double>, ptr %scevgep781, align 8
  %142 = shl i64 %index96, 3
  %scevgep327 = getelementptr i8, ptr %scevgep767, i64 %142
  %scevgep330 = getelementptr i8, ptr %scevgep327, i64 -192
  %scevgep329 = getelementptr i8, ptr %scevgep327, i64 -128
  %scevgep328 = getelementptr i8, ptr %scevgep327, i64 -64
  store <8 x double> %wide.load97, ptr %scevgep330, align 8
  store <8 x double> %wide.load98, ptr %scevgep329, align 8
  store <8 x double> %wide.load99, ptr %scevgep328, align 8
  store <8 x double> %wide.load100, ptr %scevgep327, align 8
  %index.next101 = add nuw i64 %index96, 32
  %143 = icmp eq i64 %n.vec94, %index.next101
  br i1 %143, label %middle.block102, label %vector.body95, !llvm.loop !180

middle.block102:                                  ; preds = %vector.body95
  %cmp.n103 = icmp eq i64 %arg.y.2, %n.vec94
  br i1 %cmp.n103, label %iter.check124.thread, label %vec.epilog.iter.check106

vec.epilog.iter.check106:                         ; preds = %middle.block102
  %144 = and i64 %arg.y.2, 28
  %min.epilog.iters.check107 = icmp eq i64 %144, 0
  br i1 %min.epilog.iters.check107, label %B188.us.2.preheader, label %vec.epilog.ph108, !prof !9

vec.epilog.ph108:                                 ; preds = %vec.epilog.iter.check106, %vector.main.loop.iter.check91
  %vec.epilog.resume.val104 = phi i64 [ %n.vec94, %vec.epilog.iter.check106 ], [ 0, %vector.main.loop.iter.check91 ]
  %const_mat458 = add i64 %const, 28
  %n.vec110 = and i64 %arg.y.2, %const_mat458
  br label %vec.epilog.vector.body111

vec.epilog.vector.body111:                        ; preds = %vec.epilog.vector.body111, %vec.epilog.ph108
  %index112 = phi i64 [ %vec.epilog.resume.val104, %vec.epilog.ph108 ], [ %index.next114, %vec.epilog.vector.body111 ]
  %145 = shl i64 %index112, 3
  %scevgep766 = getelementptr i8, ptr %132, i64 %145
  %wide.load113 = load <4 x double>, ptr %scevgep766, align 8
  %scevgep765 = getelementptr i8, ptr %131, i64 %145
  store <4 x double> %wide.load113, ptr %scevgep765, align 8
  %index.next114 = add nuw i64 %index112, 4
  %146 = icmp eq i64 %n.vec110, %index.next114
  br i1 %146, label %vec.epilog.middle.block115, label %vec.epilog.vector.body111, !llvm.loop !181

vec.epilog.middle.block115:                       ; preds = %vec.epilog.vector.body111
  %cmp.n116 = icmp eq i64 %arg.y.2, %n.vec110
  br i1 %cmp.n116, label %iter.check124.thread, label %B188.us.2.preheader

B188.us.2.preheader:                              ; preds = %vec.epilog.middle.block115, %vec.epilog.iter.check106, %vector.memcheck83, %iter.check89
  %147 = phi ptr [ %130, %iter.check89 ], [ %131, %vec.epilog.iter.check106 ], [ %131, %vector.memcheck83 ], [ %131, %vec.epilog.middle.block115 ]
  %148 = phi ptr [ %128, %iter.check89 ], [ %132, %vec.epilog.iter.check106 ], [ %132, %vector.memcheck83 ], [ %132, %vec.epilog.middle.block115 ]
  %.idx19 = phi i64 [ %.idx, %iter.check89 ], [ %.idx18, %vec.epilog.iter.check106 ], [ %.idx18, %vector.memcheck83 ], [ %.idx18, %vec.epilog.middle.block115 ]
  %.3583816 = phi i64 [ %.35839, %iter.check89 ], [ %.3583817, %vec.epilog.iter.check106 ], [ %.3583817, %vector.memcheck83 ], [ %.3583817, %vec.epilog.middle.block115 ]
  %.568428430.us.2.ph = phi i64 [ 0, %iter.check89 ], [ %n.vec94, %vec.epilog.iter.check106 ], [ 0, %vector.memcheck83 ], [ %n.vec110, %vec.epilog.middle.block115 ]
  %149 = sub nsw i64 %arg.y.2, %.568428430.us.2.ph
  %xtraiter370 = and i64 %149, 7
  %lcmp.mod371.not = icmp eq i64 %xtraiter370, 0
  br i1 %lcmp.mod371.not, label %B188.us.2.prol.loopexit, label %B188.us.2.prol.preheader

B188.us.2.prol.preheader:                         ; preds = %B188.us.2.preheader
  br label %B188.us.2.prol

B188.us.2.prol:                                   ; preds = %B188.us.2.prol.preheader, %B188.us.2.prol
  %lsr.iv763 = phi i64 [ %lsr.iv.next764, %B188.us.2.prol ], [ %xtraiter370, %B188.us.2.prol.preheader ]
  %.568428430.us.2.prol = phi i64 [ %.575.us.2.prol, %B188.us.2.prol ], [ %.568428430.us.2.ph, %B188.us.2.prol.preheader ]
  %.575.us.2.prol = add nuw i64 %.568428430.us.2.prol, 1
  %150 = shl i64 %.568428430.us.2.prol, 3
  %scevgep762 = getelementptr i8, ptr %148, i64 %150
  %.652.us.2.prol = load double, ptr %scevgep762, align 8
  %scevgep761 = getelementptr i8, ptr %147, i64 %150
  store double %.652.us.2.prol, ptr %scevgep761, align 8
  %lsr.iv.next764 = add nsw i64 %lsr.iv763, -1
  %prol.iter372.cmp.not = icmp eq i64 %lsr.iv.next764, 0
  br i1 %prol.iter372.cmp.not, label %B188.us.2.prol.loopexit, label %B188.us.2.prol, !llvm.loop !182

B188.us.2.prol.loopexit:                          ; preds = %B188.us.2.prol, %B188.us.2.preheader
  %.568428430.us.2.unr = phi i64 [ %.568428430.us.2.ph, %B188.us.2.preheader ], [ %.575.us.2.prol, %B188.us.2.prol ]
  %151 = sub nsw i64 %.568428430.us.2.ph, %arg.y.2
  %152 = icmp ugt i64 %151, -8
  br i1 %152, label %iter.check124, label %B188.us.2.preheader401

B188.us.2.preheader401:                           ; preds = %B188.us.2.prol.loopexit
  %153 = mul i64 %arg.y.2, 24
  %154 = getelementptr i8, ptr %arg.row.4, i64 %153
  %scevgep729 = getelementptr i8, ptr %154, i64 72
  %155 = getelementptr i8, ptr %arg.F.4, i64 %.idx19
  %scevgep745 = getelementptr i8, ptr %155, i64 56
  br label %B188.us.2

B188.us.2:                                        ; preds = %B188.us.2, %B188.us.2.preheader401
  %.568428430.us.2 = phi i64 [ %.575.us.2.7, %B188.us.2 ], [ %.568428430.us.2.unr, %B188.us.2.preheader401 ]
  %156 = shl i64 %.568428430.us.2, 3
  %scevgep757 = getelementptr i8, ptr %scevgep745, i64 %156
  %scevgep758 = getelementptr i8, ptr %scevgep757, i64 -56
  %.652.us.2 = load double, ptr %scevgep758, align 8
  %scevgep741 = getelementptr i8, ptr %scevgep729, i64 %156
  %scevgep742 = getelementptr i8, ptr %scevgep741, i64 -56
  store double %.652.us.2, ptr %scevgep742, align 8
  %157 = shl i64 %.568428430.us.2, 3
  %scevgep325 = getelementptr i8, ptr %scevgep745, i64 %157
  %scevgep326 = getelementptr i8, ptr %scevgep325, i64 -48
  %.652.us.2.1 = load double, ptr %scevgep326, align 8
  %158 = shl i64 %.568428430.us.2, 3
  %scevgep313 = getelementptr i8, ptr %scevgep729, i64 %158
  %scevgep314 = getelementptr i8, ptr %scevgep313, i64 -48
  store double %.652.us.2.1, ptr %scevgep314, align 8
  %scevgep323 = getelementptr i8, ptr %scevgep745, i64 %158
  %scevgep324 = getelementptr i8, ptr %scevgep323, i64 -40
  %.652.us.2.2 = load double, ptr %scevgep324, align 8
  %159 = shl i64 %.568428430.us.2, 3
  %scevgep311 = getelementptr i8, ptr %scevgep729, i64 %159
  %scevgep312 = getelementptr i8, ptr %scevgep311, i64 -40
  store double %.652.us.2.2, ptr %scevgep312, align 8
  %scevgep321 = getelementptr i8, ptr %scevgep745, i64 %159
  %scevgep322 = getelementptr i8, ptr %scevgep321, i64 -32
  %.652.us.2.3 = load double, ptr %scevgep322, align 8
  %160 = shl i64 %.568428430.us.2, 3
  %scevgep309 = getelementptr i8, ptr %scevgep729, i64 %160
  %scevgep310 = getelementptr i8, ptr %scevgep309, i64 -32
  store double %.652.us.2.3, ptr %scevgep310, align 8
  %scevgep319 = getelementptr i8, ptr %scevgep745, i64 %160
  %scevgep320 = getelementptr i8, ptr %scevgep319, i64 -24
  %.652.us.2.4 = load double, ptr %scevgep320, align 8
  %161 = shl i64 %.568428430.us.2, 3
  %scevgep307 = getelementptr i8, ptr %scevgep729, i64 %161
  %scevgep308 = getelementptr i8, ptr %scevgep307, i64 -24
  store double %.652.us.2.4, ptr %scevgep308, align 8
  %scevgep317 = getelementptr i8, ptr %scevgep745, i64 %161
  %scevgep318 = getelementptr i8, ptr %scevgep317, i64 -16
  %.652.us.2.5 = load double, ptr %scevgep318, align 8
  %162 = shl i64 %.568428430.us.2, 3
  %scevgep305 = getelementptr i8, ptr %scevgep729, i64 %162
  %scevgep306 = getelementptr i8, ptr %scevgep305, i64 -16
  store double %.652.us.2.5, ptr %scevgep306, align 8
  %scevgep315 = getelementptr i8, ptr %scevgep745, i64 %162
  %scevgep316 = getelementptr i8, ptr %scevgep315, i64 -8
  %.652.us.2.6 = load double, ptr %scevgep316, align 8
  %163 = shl i64 %.568428430.us.2, 3
  %scevgep303 = getelementptr i8, ptr %scevgep729, i64 %163
  %scevgep304 = getelementptr i8, ptr %scevgep303, i64 -8
  store double %.652.us.2.6, ptr %scevgep304, align 8
  %.575.us.2.7 = add nuw nsw i64 %.568428430.us.2, 8
  %.652.us.2.7 = load double, ptr %scevgep757, align 8
  store double %.652.us.2.7, ptr %scevgep741, align 8
  %exitcond460.2.not.7 = icmp eq i64 %arg.y.2, %.575.us.2.7
  br i1 %exitcond460.2.not.7, label %iter.check124.thread, label %B188.us.2, !llvm.loop !183

iter.check124.thread:                             ; preds = %B188.us.2, %vec.epilog.middle.block115, %middle.block102
  %.idx46622.pre-phi = phi i64 [ %135, %middle.block102 ], [ %135, %vec.epilog.middle.block115 ], [ %153, %B188.us.2 ]
  %.3583815.ph = phi i64 [ %.3583817, %middle.block102 ], [ %.3583817, %vec.epilog.middle.block115 ], [ %.3583816, %B188.us.2 ]
  %.idx46521 = mul i64 %arg.F.5.1, 24
  %164 = getelementptr i8, ptr %arg.F.4, i64 %.idx46521
  %165 = getelementptr i8, ptr %arg.row.4, i64 %.idx46622.pre-phi
  %166 = getelementptr double, ptr %165, i64 %.3583815.ph
  br label %vector.memcheck118

iter.check124:                                    ; preds = %B188.us.2.prol.loopexit
  %167 = icmp ult i64 %arg.y.2, 4
  %.idx465 = mul i64 %arg.F.5.1, 24
  %168 = getelementptr i8, ptr %arg.F.4, i64 %.idx465
  %.idx466 = mul i64 %arg.y.2, 24
  %169 = getelementptr i8, ptr %arg.row.4, i64 %.idx466
  %170 = getelementptr double, ptr %169, i64 %.3583816
  br i1 %167, label %B188.us.3.preheader, label %vector.memcheck118

vector.memcheck118:                               ; preds = %iter.check124.thread, %iter.check124
  %171 = phi ptr [ %166, %iter.check124.thread ], [ %170, %iter.check124 ]
  %172 = phi ptr [ %164, %iter.check124.thread ], [ %168, %iter.check124 ]
  %.idx46527 = phi i64 [ %.idx46521, %iter.check124.thread ], [ %.idx465, %iter.check124 ]
  %.358381526 = phi i64 [ %.3583815.ph, %iter.check124.thread ], [ %.3583816, %iter.check124 ]
  %173 = ptrtoint ptr %arg.row.4 to i64
  %174 = ptrtoint ptr %arg.F.4 to i64
  %175 = shl i64 %arg.y.2, 5
  %.neg62 = add i64 %173, 16
  %176 = add i64 %.neg62, %175
  %177 = add i64 %.idx46527, %174
  %178 = sub i64 %176, %177
  %diff.check121 = icmp ult i64 %178, 256
  br i1 %diff.check121, label %B188.us.3.preheader, label %vector.main.loop.iter.check126

vector.main.loop.iter.check126:                   ; preds = %vector.memcheck118
  %min.iters.check125 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check125, label %vec.epilog.ph143, label %vector.ph127

vector.ph127:                                     ; preds = %vector.main.loop.iter.check126
  %n.vec129 = and i64 %arg.y.2, %const
  %179 = getelementptr i8, ptr %arg.row.4, i64 %175
  %scevgep713 = getelementptr i8, ptr %179, i64 208
  %180 = getelementptr i8, ptr %arg.F.4, i64 %.idx46527
  %scevgep721 = getelementptr i8, ptr %180, i64 192
  br label %vector.body130

vector.body130:                                   ; preds = %vector.body130, %vector.ph127
  %index131 = phi i64 [ 0, %vector.ph127 ], [ %index.next136, %vector.body130 ]
  %181 = shl i64 %index131, 3
  %scevgep727 = getelementptr i8, ptr %scevgep721, i64 %181
  %scevgep728 = getelementptr i8, ptr %scevgep727, i64 -192
  %scevgep726 = getelementptr i8, ptr %scevgep727, i64 -128
  %scevgep724 = getelementptr i8, ptr %scevgep727, i64 -64
  %wide.load132 = load <8 x double>, ptr %scevgep728, align 8
  %wide.load133 = load <8 x double>, ptr %scevgep726, align 8
  %wide.load134 = load <8 x double>, ptr %scevgep724, align 8
  %wide.load135 = load <8 x double>, ptr %scevgep727, align 8
  %182 = shl i64 %index131, 3
  %scevgep299 = getelementptr i8, ptr %scevgep713, i64 %182
  %scevgep302 = getelementptr i8, ptr %scevgep299, i64 -192
  %scevgep301 = getelementptr i8, ptr %scevgep299, i64 -128
  %scevgep300 = getelementptr i8, ptr %scevgep299, i64 -64
  store <8 x double> %wide.load132, ptr %scevgep302, align 8
  store <8 x double> %wide.load133, ptr %scevgep301, align 8
  store <8 x double> %wide.load134, ptr %scevgep300, align 8
  store <8 x double> %wide.load135, ptr %scevgep299, align 8
  %index.next136 = add nuw i64 %index131, 32
  %183 = icmp eq i64 %n.vec129, %index.next136
  br i1 %183, label %middle.block137, label %vector.body130, !llvm.loop !184

middle.block137:                                  ; preds = %vector.body130
  %cmp.n138 = icmp eq i64 %arg.y.2, %n.vec129
  br i1 %cmp.n138, label %iter.check159.thread, label %vec.epilog.iter.check141

vec.epilog.iter.check141:                         ; preds = %middle.block137
  %184 = and i64 %arg.y.2, 28
  %min.epilog.iters.check142 = icmp eq i64 %184, 0
  br i1 %min.epilog.iters.check142, label %B188.us.3.preheader, label %vec.epilog.ph143, !prof !9

vec.epilog.ph143:                                 ; preds = %vec.epilog.iter.check141, %vector.main.loop.iter.check126
  %vec.epilog.resume.val139 = phi i64 [ %n.vec129, %vec.epilog.iter.check141 ], [ 0, %vector.main.loop.iter.check126 ]
  %const_mat459 = add i64 %const, 28
  %n.vec145 = and i64 %arg.y.2, %const_mat459
  br label %vec.epilog.vector.body146

vec.epilog.vector.body146:                        ; preds = %vec.epilog.vector.body146, %vec.epilog.ph143
  %index147 = phi i64 [ %vec.epilog.resume.val139, %vec.epilog.ph143 ], [ %index.next149, %vec.epilog.vector.body146 ]
  %185 = shl i64 %index147, 3
  %scevgep712 = getelementptr i8, ptr %172, i64 %185
  %wide.load148 = load <4 x double>, ptr %scevgep712, align 8
  %scevgep711 = getelementptr i8, ptr %171, i64 %185
  store <4 x double> %wide.load148, ptr %scevgep711, align 8
  %index.next149 = add nuw i64 %index147, 4
  %186 = icmp eq i64 %n.vec145, %index.next149
  br i1 %186, label %vec.epilog.middle.block150, label %vec.epilog.vector.body146, !llvm.loop !185

vec.epilog.middle.block150:                       ; preds = %vec.epilog.vector.body146
  %cmp.n151 = icmp eq i64 %arg.y.2, %n.vec145
  br i1 %cmp.n151, label %iter.check159.thread, label %B188.us.3.preheader

B188.us.3.preheader:                              ; preds = %vec.epilog.middle.block150, %vec.epilog.iter.check141, %vector.memcheck118, %iter.check124
  %187 = phi ptr [ %170, %iter.check124 ], [ %171, %vec.epilog.iter.check141 ], [ %171, %vector.memcheck118 ], [ %171, %vec.epilog.middle.block150 ]
  %188 = phi ptr [ %168, %iter.check124 ], [ %172, %vec.epilog.iter.check141 ], [ %172, %vector.memcheck118 ], [ %172, %vec.epilog.middle.block150 ]
  %.idx46528 = phi i64 [ %.idx465, %iter.check124 ], [ %.idx46527, %vec.epilog.iter.check141 ], [ %.idx46527, %vector.memcheck118 ], [ %.idx46527, %vec.epilog.middle.block150 ]
  %.358381525 = phi i64 [ %.3583816, %iter.check124 ], [ %.358381526, %vec.epilog.iter.check141 ], [ %.358381526, %vector.memcheck118 ], [ %.358381526, %vec.epilog.middle.block150 ]
  %.568428430.us.3.ph = phi i64 [ 0, %iter.check124 ], [ %n.vec129, %vec.epilog.iter.check141 ], [ 0, %vector.memcheck118 ], [ %n.vec145, %vec.epilog.middle.block150 ]
  %189 = sub nsw i64 %arg.y.2, %.568428430.us.3.ph
  %xtraiter373 = and i64 %189, 7
  %lcmp.mod374.not = icmp eq i64 %xtraiter373, 0
  br i1 %lcmp.mod374.not, label %B188.us.3.prol.loopexit, label %B188.us.3.prol.preheader

B188.us.3.prol.preheader:                         ; preds = %B188.us.3.preheader
  br label %B188.us.3.prol

B188.us.3.prol:                                   ; preds = %B188.us.3.prol.preheader, %B188.us.3.prol
  %lsr.iv709 = phi i64 [ %lsr.iv.next710, %B188.us.3.prol ], [ %xtraiter373, %B188.us.3.prol.preheader ]
  %.568428430.us.3.prol = phi i64 [ %.575.us.3.prol, %B188.us.3.prol ], [ %.568428430.us.3.ph, %B188.us.3.prol.preheader ]
  %.575.us.3.prol = add nuw i64 %.568428430.us.3.prol, 1
  %190 = shl i64 %.568428430.us.3.prol, 3
  %scevgep708 = getelementptr i8, ptr %188, i64 %190
  %.652.us.3.prol = load double, ptr %scevgep708, align 8
  %scevgep707 = getelementptr i8, ptr %187, i64 %190
  store double %.652.us.3.prol, ptr %scevgep707, align 8
  %lsr.iv.next710 = add nsw i64 %lsr.iv709, -1
  %prol.iter375.cmp.not = icmp eq i64 %lsr.iv.next710, 0
  br i1 %prol.iter375.cmp.not, label %B188.us.3.prol.loopexit, label %B188.us.3.prol, !llvm.loop !186

B188.us.3.prol.loopexit:                          ; preds = %B188.us.3.prol, %B188.us.3.preheader
  %.568428430.us.3.unr = phi i64 [ %.568428430.us.3.ph, %B188.us.3.preheader ], [ %.575.us.3.prol, %B188.us.3.prol ]
  %191 = sub nsw i64 %.568428430.us.3.ph, %arg.y.2
  %192 = icmp ugt i64 %191, -8
  br i1 %192, label %iter.check159, label %B188.us.3.preheader400

B188.us.3.preheader400:                           ; preds = %B188.us.3.prol.loopexit
  %193 = shl i64 %arg.y.2, 5
  %194 = getelementptr i8, ptr %arg.row.4, i64 %193
  %scevgep675 = getelementptr i8, ptr %194, i64 72
  %195 = getelementptr i8, ptr %arg.F.4, i64 %.idx46528
  %scevgep691 = getelementptr i8, ptr %195, i64 56
  br label %B188.us.3

B188.us.3:                                        ; preds = %B188.us.3, %B188.us.3.preheader400
  %.568428430.us.3 = phi i64 [ %.575.us.3.7, %B188.us.3 ], [ %.568428430.us.3.unr, %B188.us.3.preheader400 ]
  %196 = shl i64 %.568428430.us.3, 3
  %scevgep703 = getelementptr i8, ptr %scevgep691, i64 %196
  %scevgep704 = getelementptr i8, ptr %scevgep703, i64 -56
  %.652.us.3 = load double, ptr %scevgep704, align 8
  %scevgep687 = getelementptr i8, ptr %scevgep675, i64 %196
  %scevgep688 = getelementptr i8, ptr %scevgep687, i64 -56
  store double %.652.us.3, ptr %scevgep688, align 8
  %197 = shl i64 %.568428430.us.3, 3
  %scevgep297 = getelementptr i8, ptr %scevgep691, i64 %197
  %scevgep298 = getelementptr i8, ptr %scevgep297, i64 -48
  %.652.us.3.1 = load double, ptr %scevgep298, align 8
  %198 = shl i64 %.568428430.us.3, 3
  %scevgep285 = getelementptr i8, ptr %scevgep675, i64 %198
  %scevgep286 = getelementptr i8, ptr %scevgep285, i64 -48
  store double %.652.us.3.1, ptr %scevgep286, align 8
  %scevgep295 = getelementptr i8, ptr %scevgep691, i64 %198
  %scevgep296 = getelementptr i8, ptr %scevgep295, i64 -40
  %.652.us.3.2 = load double, ptr %scevgep296, align 8
  %199 = shl i64 %.568428430.us.3, 3
  %scevgep283 = getelementptr i8, ptr %scevgep675, i64 %199
  %scevgep284 = getelementptr i8, ptr %scevgep283, i64 -40
  store double %.652.us.3.2, ptr %scevgep284, align 8
  %scevgep293 = getelementptr i8, ptr %scevgep691, i64 %199
  %scevgep294 = getelementptr i8, ptr %scevgep293, i64 -32
  %.652.us.3.3 = load double, ptr %scevgep294, align 8
  %200 = shl i64 %.568428430.us.3, 3
  %scevgep281 = getelementptr i8, ptr %scevgep675, i64 %200
  %scevgep282 = getelementptr i8, ptr %scevgep281, i64 -32
  store double %.652.us.3.3, ptr %scevgep282, align 8
  %scevgep291 = getelementptr i8, ptr %scevgep691, i64 %200
  %scevgep292 = getelementptr i8, ptr %scevgep291, i64 -24
  %.652.us.3.4 = load double, ptr %scevgep292, align 8
  %201 = shl i64 %.568428430.us.3, 3
  %scevgep279 = getelementptr i8, ptr %scevgep675, i64 %201
  %scevgep280 = getelementptr i8, ptr %scevgep279, i64 -24
  store double %.652.us.3.4, ptr %scevgep280, align 8
  %scevgep289 = getelementptr i8, ptr %scevgep691, i64 %201
  %scevgep290 = getelementptr i8, ptr %scevgep289, i64 -16
  %.652.us.3.5 = load double, ptr %scevgep290, align 8
  %202 = shl i64 %.568428430.us.3, 3
  %scevgep277 = getelementptr i8, ptr %scevgep675, i64 %202
  %scevgep278 = getelementptr i8, ptr %scevgep277, i64 -16
  store double %.652.us.3.5, ptr %scevgep278, align 8
  %scevgep287 = getelementptr i8, ptr %scevgep691, i64 %202
  %scevgep288 = getelementptr i8, ptr %scevgep287, i64 -8
  %.652.us.3.6 = load double, ptr %scevgep288, align 8
  %203 = shl i64 %.568428430.us.3, 3
  %scevgep275 = getelementptr i8, ptr %scevgep675, i64 %203
  %scevgep276 = getelementptr i8, ptr %scevgep275, i64 -8
  store double %.652.us.3.6, ptr %scevgep276, align 8
  %.575.us.3.7 = add nuw nsw i64 %.568428430.us.3, 8
  %.652.us.3.7 = load double, ptr %scevgep703, align 8
  store double %.652.us.3.7, ptr %scevgep687, align 8
  %exitcond460.3.not.7 = icmp eq i64 %arg.y.2, %.575.us.3.7
  br i1 %exitcond460.3.not.7, label %iter.check159.thread, label %B188.us.3, !llvm.loop !187

iter.check159.thread:                             ; preds = %B188.us.3, %vec.epilog.middle.block150, %middle.block137
  %.idx46831.pre-phi = phi i64 [ %175, %middle.block137 ], [ %175, %vec.epilog.middle.block150 ], [ %193, %B188.us.3 ]
  %.358381524.ph = phi i64 [ %.358381526, %middle.block137 ], [ %.358381526, %vec.epilog.middle.block150 ], [ %.358381525, %B188.us.3 ]
  %.idx46730 = shl i64 %arg.F.5.1, 5
  %204 = getelementptr i8, ptr %arg.F.4, i64 %.idx46730
  %205 = getelementptr i8, ptr %arg.row.4, i64 %.idx46831.pre-phi
  %206 = getelementptr double, ptr %205, i64 %.358381524.ph
  br label %vector.memcheck153

iter.check159:                                    ; preds = %B188.us.3.prol.loopexit
  %207 = icmp ult i64 %arg.y.2, 4
  %.idx467 = shl i64 %arg.F.5.1, 5
  %208 = getelementptr i8, ptr %arg.F.4, i64 %.idx467
  %.idx468 = shl i64 %arg.y.2, 5
  %209 = getelementptr i8, ptr %arg.row.4, i64 %.idx468
  %210 = getelementptr double, ptr %209, i64 %.358381525
  br i1 %207, label %B188.us.4.preheader, label %vector.memcheck153

vector.memcheck153:                               ; preds = %iter.check159.thread, %iter.check159
  %211 = phi ptr [ %206, %iter.check159.thread ], [ %210, %iter.check159 ]
  %212 = phi ptr [ %204, %iter.check159.thread ], [ %208, %iter.check159 ]
  %.idx46736 = phi i64 [ %.idx46730, %iter.check159.thread ], [ %.idx467, %iter.check159 ]
  %.35838152435 = phi i64 [ %.358381524.ph, %iter.check159.thread ], [ %.358381525, %iter.check159 ]
  %213 = ptrtoint ptr %arg.row.4 to i64
  %214 = ptrtoint ptr %arg.F.4 to i64
  %215 = mul i64 %arg.y.2, 40
  %.neg64 = add i64 %213, 16
  %216 = add i64 %.neg64, %215
  %217 = add i64 %.idx46736, %214
  %218 = sub i64 %216, %217
  %diff.check156 = icmp ult i64 %218, 256
  br i1 %diff.check156, label %B188.us.4.preheader, label %vector.main.loop.iter.check161

vector.main.loop.iter.check161:                   ; preds = %vector.memcheck153
  %min.iters.check160 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check160, label %vec.epilog.ph178, label %vector.ph162

vector.ph162:                                     ; preds = %vector.main.loop.iter.check161
  %n.vec164 = and i64 %arg.y.2, %const
  %219 = getelementptr i8, ptr %arg.row.4, i64 %215
  %scevgep659 = getelementptr i8, ptr %219, i64 208
  %220 = getelementptr i8, ptr %arg.F.4, i64 %.idx46736
  %scevgep667 = getelementptr i8, ptr %220, i64 192
  br label %vector.body165

vector.body165:                                   ; preds = %vector.body165, %vector.ph162
  %index166 = phi i64 [ 0, %vector.ph162 ], [ %index.next171, %vector.body165 ]
  %221 = shl i64 %index166, 3
  %scevgep673 = getelementptr i8, ptr %scevgep667, i64 %221
  %scevgep674 = getelementptr i8, ptr %scevgep673, i64 -192
  %scevgep672 = getelementptr i8, ptr %scevgep673, i64 -128
  %scevgep670 = getelementptr i8, ptr %scevgep673, i64 -64
  %wide.load167 = load <8 x double>, ptr %scevgep674, align 8
  %wide.load168 = load <8 x double>, ptr %scevgep672, align 8
  %wide.load169 = load <8 x double>, ptr %scevgep670, align 8
  %wide.load170 = load <8 x double>, ptr %scevgep673, align 8
  %222 = shl i64 %index166, 3
  %scevgep271 = getelementptr i8, ptr %scevgep659, i64 %222
  %scevgep274 = getelementptr i8, ptr %scevgep271, i64 -192
  %scevgep273 = getelementptr i8, ptr %scevgep271, i64 -128
  %scevgep272 = getelementptr i8, ptr %scevgep271, i64 -64
  store <8 x double> %wide.load167, ptr %scevgep274, align 8
  store <8 x double> %wide.load168, ptr %scevgep273, align 8
  store <8 x double> %wide.load169, ptr %scevgep272, align 8
  store <8 x double> %wide.load170, ptr %scevgep271, align 8
  %index.next171 = add nuw i64 %index166, 32
  %223 = icmp eq i64 %n.vec164, %index.next171
  br i1 %223, label %middle.block172, label %vector.body165, !llvm.loop !188

middle.block172:                                  ; preds = %vector.body165
  %cmp.n173 = icmp eq i64 %arg.y.2, %n.vec164
  br i1 %cmp.n173, label %iter.check194.thread, label %vec.epilog.iter.check176

vec.epilog.iter.check176:                         ; preds = %middle.block172
  %224 = and i64 %arg.y.2, 28
  %min.epilog.iters.check177 = icmp eq i64 %224, 0
  br i1 %min.epilog.iters.check177, label %B188.us.4.preheader, label %vec.epilog.ph178, !prof !9

vec.epilog.ph178:                                 ; preds = %vec.epilog.iter.check176, %vector.main.loop.iter.check161
  %vec.epilog.resume.val174 = phi i64 [ %n.vec164, %vec.epilog.iter.check176 ], [ 0, %vector.main.loop.iter.check161 ]
  %const_mat460 = add i64 %const, 28
  %n.vec180 = and i64 %arg.y.2, %const_mat460
  br label %vec.epilog.vector.body181

vec.epilog.vector.body181:                        ; preds = %vec.epilog.vector.body181, %vec.epilog.ph178
  %index182 = phi i64 [ %vec.epilog.resume.val174, %vec.epilog.ph178 ], [ %index.next184, %vec.epilog.vector.body181 ]
  %225 = shl i64 %index182, 3
  %scevgep658 = getelementptr i8, ptr %212, i64 %225
  %wide.load183 = load <4 x double>, ptr %scevgep658, align 8
  %scevgep657 = getelementptr i8, ptr %211, i64 %225
  store <4 x double> %wide.load183, ptr %scevgep657, align 8
  %index.next184 = add nuw i64 %index182, 4
  %226 = icmp eq i64 %n.vec180, %index.next184
  br i1 %226, label %vec.epilog.middle.block185, label %vec.epilog.vector.body181, !llvm.loop !189

vec.epilog.middle.block185:                       ; preds = %vec.epilog.vector.body181
  %cmp.n186 = icmp eq i64 %arg.y.2, %n.vec180
  br i1 %cmp.n186, label %iter.check194.thread, label %B188.us.4.preheader

B188.us.4.preheader:                              ; preds = %vec.epilog.middle.block185, %vec.epilog.iter.check176, %vector.memcheck153, %iter.check159
  %227 = phi ptr [ %210, %iter.check159 ], [ %211, %vec.epilog.iter.check176 ], [ %211, %vector.memcheck153 ], [ %211, %vec.epilog.middle.block185 ]
  %228 = phi ptr [ %208, %iter.check159 ], [ %212, %vec.epilog.iter.check176 ], [ %212, %vector.memcheck153 ], [ %212, %vec.epilog.middle.block185 ]
  %.idx46737 = phi i64 [ %.idx467, %iter.check159 ], [ %.idx46736, %vec.epilog.iter.check176 ], [ %.idx46736, %vector.memcheck153 ], [ %.idx46736, %vec.epilog.middle.block185 ]
  %.35838152434 = phi i64 [ %.358381525, %iter.check159 ], [ %.35838152435, %vec.epilog.iter.check176 ], [ %.35838152435, %vector.memcheck153 ], [ %.35838152435, %vec.epilog.middle.block185 ]
  %.568428430.us.4.ph = phi i64 [ 0, %iter.check159 ], [ %n.vec164, %vec.epilog.iter.check176 ], [ 0, %vector.memcheck153 ], [ %n.vec180, %vec.epilog.middle.block185 ]
  %229 = sub nsw i64 %arg.y.2, %.568428430.us.4.ph
  %xtraiter376 = and i64 %229, 7
  %lcmp.mod377.not = icmp eq i64 %xtraiter376, 0
  br i1 %lcmp.mod377.not, label %B188.us.4.prol.loopexit, label %B188.us.4.prol.preheader

B188.us.4.prol.preheader:                         ; preds = %B188.us.4.preheader
  br label %B188.us.4.prol

B188.us.4.prol:                                   ; preds = %B188.us.4.prol.preheader, %B188.us.4.prol
  %lsr.iv655 = phi i64 [ %lsr.iv.next656, %B188.us.4.prol ], [ %xtraiter376, %B188.us.4.prol.preheader ]
  %.568428430.us.4.prol = phi i64 [ %.575.us.4.prol, %B188.us.4.prol ], [ %.568428430.us.4.ph, %B188.us.4.prol.preheader ]
  %.575.us.4.prol = add nuw i64 %.568428430.us.4.prol, 1
  %230 = shl i64 %.568428430.us.4.prol, 3
  %scevgep654 = getelementptr i8, ptr %228, i64 %230
  %.652.us.4.prol = load double, ptr %scevgep654, align 8
  %scevgep653 = getelementptr i8, ptr %227, i64 %230
  store double %.652.us.4.prol, ptr %scevgep653, align 8
  %lsr.iv.next656 = add nsw i64 %lsr.iv655, -1
  %prol.iter378.cmp.not = icmp eq i64 %lsr.iv.next656, 0
  br i1 %prol.iter378.cmp.not, label %B188.us.4.prol.loopexit, label %B188.us.4.prol, !llvm.loop !190

B188.us.4.prol.loopexit:                          ; preds = %B188.us.4.prol, %B188.us.4.preheader
  %.568428430.us.4.unr = phi i64 [ %.568428430.us.4.ph, %B188.us.4.preheader ], [ %.575.us.4.prol, %B188.us.4.prol ]
  %231 = sub nsw i64 %.568428430.us.4.ph, %arg.y.2
  %232 = icmp ugt i64 %231, -8
  br i1 %232, label %iter.check194, label %B188.us.4.preheader399

B188.us.4.preheader399:                           ; preds = %B188.us.4.prol.loopexit
  %233 = mul i64 %arg.y.2, 40
  %234 = getelementptr i8, ptr %arg.row.4, i64 %233
  %scevgep621 = getelementptr i8, ptr %234, i64 72
  %235 = getelementptr i8, ptr %arg.F.4, i64 %.idx46737
  %scevgep637 = getelementptr i8, ptr %235, i64 56
  br label %B188.us.4

B188.us.4:                                        ; preds = %B188.us.4, %B188.us.4.preheader399
  %.568428430.us.4 = phi i64 [ %.575.us.4.7, %B188.us.4 ], [ %.568428430.us.4.unr, %B188.us.4.preheader399 ]
  %236 = shl i64 %.568428430.us.4, 3
  %scevgep649 = getelementptr i8, ptr %scevgep637, i64 %236
  %scevgep650 = getelementptr i8, ptr %scevgep649, i64 -56
  %.652.us.4 = load double, ptr %scevgep650, align 8
  %scevgep633 = getelementptr i8, ptr %scevgep621, i64 %236
  %scevgep634 = getelementptr i8, ptr %scevgep633, i64 -56
  store double %.652.us.4, ptr %scevgep634, align 8
  %237 = shl i64 %.568428430.us.4, 3
  %scevgep269 = getelementptr i8, ptr %scevgep637, i64 %237
  %scevgep270 = getelementptr i8, ptr %scevgep269, i64 -48
  %.652.us.4.1 = load double, ptr %scevgep270, align 8
  %238 = shl i64 %.568428430.us.4, 3
  %scevgep257 = getelementptr i8, ptr %scevgep621, i64 %238
  %scevgep258 = getelementptr i8, ptr %scevgep257, i64 -48
  store double %.652.us.4.1, ptr %scevgep258, align 8
  %scevgep267 = getelementptr i8, ptr %scevgep637, i64 %238
  %scevgep268 = getelementptr i8, ptr %scevgep267, i64 -40
  %.652.us.4.2 = load double, ptr %scevgep268, align 8
  %239 = shl i64 %.568428430.us.4, 3
  %scevgep255 = getelementptr i8, ptr %scevgep621, i64 %239
  %scevgep256 = getelementptr i8, ptr %scevgep255, i64 -40
  store double %.652.us.4.2, ptr %scevgep256, align 8
  %scevgep265 = getelementptr i8, ptr %scevgep637, i64 %239
  %scevgep266 = getelementptr i8, ptr %scevgep265, i64 -32
  %.652.us.4.3 = load double, ptr %scevgep266, align 8
  %240 = shl i64 %.568428430.us.4, 3
  %scevgep253 = getelementptr i8, ptr %scevgep621, i64 %240
  %scevgep254 = getelementptr i8, ptr %scevgep253, i64 -32
  store double %.652.us.4.3, ptr %scevgep254, align 8
  %scevgep263 = getelementptr i8, ptr %scevgep637, i64 %240
  %scevgep264 = getelementptr i8, ptr %scevgep263, i64 -24
  %.652.us.4.4 = load double, ptr %scevgep264, align 8
  %241 = shl i64 %.568428430.us.4, 3
  %scevgep251 = getelementptr i8, ptr %scevgep621, i64 %241
  %scevgep252 = getelementptr i8, ptr %scevgep251, i64 -24
  store double %.652.us.4.4, ptr %scevgep252, align 8
  %scevgep261 = getelementptr i8, ptr %scevgep637, i64 %241
  %scevgep262 = getelementptr i8, ptr %scevgep261, i64 -16
  %.652.us.4.5 = load double, ptr %scevgep262, align 8
  %242 = shl i64 %.568428430.us.4, 3
  %scevgep249 = getelementptr i8, ptr %scevgep621, i64 %242
  %scevgep250 = getelementptr i8, ptr %scevgep249, i64 -16
  store double %.652.us.4.5, ptr %scevgep250, align 8
  %scevgep259 = getelementptr i8, ptr %scevgep637, i64 %242
  %scevgep260 = getelementptr i8, ptr %scevgep259, i64 -8
  %.652.us.4.6 = load double, ptr %scevgep260, align 8
  %243 = shl i64 %.568428430.us.4, 3
  %scevgep247 = getelementptr i8, ptr %scevgep621, i64 %243
  %scevgep248 = getelementptr i8, ptr %scevgep247, i64 -8
  store double %.652.us.4.6, ptr %scevgep248, align 8
  %.575.us.4.7 = add nuw nsw i64 %.568428430.us.4, 8
  %.652.us.4.7 = load double, ptr %scevgep649, align 8
  store double %.652.us.4.7, ptr %scevgep633, align 8
  %exitcond460.4.not.7 = icmp eq i64 %arg.y.2, %.575.us.4.7
  br i1 %exitcond460.4.not.7, label %iter.check194.thread, label %B188.us.4, !llvm.loop !191

iter.check194.thread:                             ; preds = %B188.us.4, %vec.epilog.middle.block185, %middle.block172
  %.idx47040.pre-phi = phi i64 [ %215, %middle.block172 ], [ %215, %vec.epilog.middle.block185 ], [ %233, %B188.us.4 ]
  %.35838152433.ph = phi i64 [ %.35838152435, %middle.block172 ], [ %.35838152435, %vec.epilog.middle.block185 ], [ %.35838152434, %B188.us.4 ]
  %.idx46939 = mul i64 %arg.F.5.1, 40
  %244 = getelementptr i8, ptr %arg.F.4, i64 %.idx46939
  %245 = getelementptr i8, ptr %arg.row.4, i64 %.idx47040.pre-phi
  %246 = getelementptr double, ptr %245, i64 %.35838152433.ph
  br label %vector.memcheck188

iter.check194:                                    ; preds = %B188.us.4.prol.loopexit
  %247 = icmp ult i64 %arg.y.2, 4
  %.idx469 = mul i64 %arg.F.5.1, 40
  %248 = getelementptr i8, ptr %arg.F.4, i64 %.idx469
  %.idx470 = mul i64 %arg.y.2, 40
  %249 = getelementptr i8, ptr %arg.row.4, i64 %.idx470
  %250 = getelementptr double, ptr %249, i64 %.35838152434
  br i1 %247, label %B188.us.5.preheader, label %vector.memcheck188

vector.memcheck188:                               ; preds = %iter.check194.thread, %iter.check194
  %251 = phi ptr [ %246, %iter.check194.thread ], [ %250, %iter.check194 ]
  %252 = phi ptr [ %244, %iter.check194.thread ], [ %248, %iter.check194 ]
  %.idx46945 = phi i64 [ %.idx46939, %iter.check194.thread ], [ %.idx469, %iter.check194 ]
  %.3583815243344 = phi i64 [ %.35838152433.ph, %iter.check194.thread ], [ %.35838152434, %iter.check194 ]
  %253 = ptrtoint ptr %arg.row.4 to i64
  %254 = ptrtoint ptr %arg.F.4 to i64
  %255 = mul i64 %arg.y.2, 48
  %.neg66 = add i64 %253, 16
  %256 = add i64 %.neg66, %255
  %257 = add i64 %.idx46945, %254
  %258 = sub i64 %256, %257
  %diff.check191 = icmp ult i64 %258, 256
  br i1 %diff.check191, label %B188.us.5.preheader, label %vector.main.loop.iter.check196

vector.main.loop.iter.check196:                   ; preds = %vector.memcheck188
  %min.iters.check195 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check195, label %vec.epilog.ph213, label %vector.ph197

vector.ph197:                                     ; preds = %vector.main.loop.iter.check196
  %n.vec199 = and i64 %arg.y.2, %const
  %259 = getelementptr i8, ptr %arg.row.4, i64 %255
  %scevgep605 = getelementptr i8, ptr %259, i64 208
  %260 = getelementptr i8, ptr %arg.F.4, i64 %.idx46945
  %scevgep613 = getelementptr i8, ptr %260, i64 192
  br label %vector.body200

vector.body200:                                   ; preds = %vector.body200, %vector.ph197
  %index201 = phi i64 [ 0, %vector.ph197 ], [ %index.next206, %vector.body200 ]
  %261 = shl i64 %index201, 3
  %scevgep619 = getelementptr i8, ptr %scevgep613, i64 %261
  %scevgep620 = getelementptr i8, ptr %scevgep619, i64 -192
  %scevgep618 = getelementptr i8, ptr %scevgep619, i64 -128
  %scevgep616 = getelementptr i8, ptr %scevgep619, i64 -64
  %wide.load202 = load <8 x double>, ptr %scevgep620, align 8
  %wide.load203 = load <8 x double>, ptr %scevgep618, align 8
  %wide.load204 = load <8 x double>, ptr %scevgep616, align 8
  %wide.load205 = load <8 x double>, ptr %scevgep619, align 8
  %262 = shl i64 %index201, 3
  %scevgep243 = getelementptr i8, ptr %scevgep605, i64 %262
  %scevgep246 = getelementptr i8, ptr %scevgep243, i64 -192
  %scevgep245 = getelementptr i8, ptr %scevgep243, i64 -128
  %scevgep244 = getelementptr i8, ptr %scevgep243, i64 -64
  store <8 x double> %wide.load202, ptr %scevgep246, align 8
  store <8 x double> %wide.load203, ptr %scevgep245, align 8
  store <8 x double> %wide.load204, ptr %scevgep244, align 8
  store <8 x double> %wide.load205, ptr %scevgep243, align 8
  %index.next206 = add nuw i64 %index201, 32
  %263 = icmp eq i64 %n.vec199, %index.next206
  br i1 %263, label %middle.block207, label %vector.body200, !llvm.loop !192

middle.block207:                                  ; preds = %vector.body200
  %cmp.n208 = icmp eq i64 %arg.y.2, %n.vec199
  br i1 %cmp.n208, label %iter.check229.thread, label %vec.epilog.iter.check211

vec.epilog.iter.check211:                         ; preds = %middle.block207
  %264 = and i64 %arg.y.2, 28
  %min.epilog.iters.check212 = icmp eq i64 %264, 0
  br i1 %min.epilog.iters.check212, label %B188.us.5.preheader, label %vec.epilog.ph213, !prof !9

vec.epilog.ph213:                                 ; preds = %vec.epilog.iter.check211, %vector.main.loop.iter.check196
  %vec.epilog.resume.val209 = phi i64 [ %n.vec199, %vec.epilog.iter.check211 ], [ 0, %vector.main.loop.iter.check196 ]
  %const_mat461 = add i64 %const, 28
  %n.vec215 = and i64 %arg.y.2, %const_mat461
  br label %vec.epilog.vector.body216

vec.epilog.vector.body216:                        ; preds = %vec.epilog.vector.body216, %vec.epilog.ph213
  %index217 = phi i64 [ %vec.epilog.resume.val209, %vec.epilog.ph213 ], [ %index.next219, %vec.epilog.vector.body216 ]
  %265 = shl i64 %index217, 3
  %scevgep604 = getelementptr i8, ptr %252, i64 %265
  %wide.load218 = load <4 x double>, ptr %scevgep604, align 8
  %scevgep603 = getelementptr i8, ptr %251, i64 %265
  store <4 x double> %wide.load218, ptr %scevgep603, align 8
  %index.next219 = add nuw i64 %index217, 4
  %266 = icmp eq i64 %n.vec215, %index.next219
  br i1 %266, label %vec.epilog.middle.block220, label %vec.epilog.vector.body216, !llvm.loop !193

vec.epilog.middle.block220:                       ; preds = %vec.epilog.vector.body216
  %cmp.n221 = icmp eq i64 %arg.y.2, %n.vec215
  br i1 %cmp.n221, label %iter.check229.thread, label %B188.us.5.preheader

B188.us.5.preheader:                              ; preds = %vec.epilog.middle.block220, %vec.epilog.iter.check211, %vector.memcheck188, %iter.check194
  %267 = phi ptr [ %250, %iter.check194 ], [ %251, %vec.epilog.iter.check211 ], [ %251, %vector.memcheck188 ], [ %251, %vec.epilog.middle.block220 ]
  %268 = phi ptr [ %248, %iter.check194 ], [ %252, %vec.epilog.iter.check211 ], [ %252, %vector.memcheck188 ], [ %252, %vec.epilog.middle.block220 ]
  %.idx46946 = phi i64 [ %.idx469, %iter.check194 ], [ %.idx46945, %vec.epilog.iter.check211 ], [ %.idx46945, %vector.memcheck188 ], [ %.idx46945, %vec.epilog.middle.block220 ]
  %.3583815243343 = phi i64 [ %.35838152434, %iter.check194 ], [ %.3583815243344, %vec.epilog.iter.check211 ], [ %.3583815243344, %vector.memcheck188 ], [ %.3583815243344, %vec.epilog.middle.block220 ]
  %.568428430.us.5.ph = phi i64 [ 0, %iter.check194 ], [ %n.vec199, %vec.epilog.iter.check211 ], [ 0, %vector.memcheck188 ], [ %n.vec215, %vec.epilog.middle.block220 ]
  %269 = sub nsw i64 %arg.y.2, %.568428430.us.5.ph
  %xtraiter379 = and i64 %269, 7
  %lcmp.mod380.not = icmp eq i64 %xtraiter379, 0
  br i1 %lcmp.mod380.not, label %B188.us.5.prol.loopexit, label %B188.us.5.prol.preheader

B188.us.5.prol.preheader:                         ; preds = %B188.us.5.preheader
  br label %B188.us.5.prol

B188.us.5.prol:                                   ; preds = %B188.us.5.prol.preheader, %B188.us.5.prol
  %lsr.iv601 = phi i64 [ %lsr.iv.next602, %B188.us.5.prol ], [ %xtraiter379, %B188.us.5.prol.preheader ]
  %.568428430.us.5.prol = phi i64 [ %.575.us.5.prol, %B188.us.5.prol ], [ %.568428430.us.5.ph, %B188.us.5.prol.preheader ]
  %.575.us.5.prol = add nuw i64 %.568428430.us.5.prol, 1
  %270 = shl i64 %.568428430.us.5.prol, 3
  %scevgep600 = getelementptr i8, ptr %268, i64 %270
  %.652.us.5.prol = load double, ptr %scevgep600, align 8
  %scevgep599 = getelementptr i8, ptr %267, i64 %270
  store double %.652.us.5.prol, ptr %scevgep599, align 8
  %lsr.iv.next602 = add nsw i64 %lsr.iv601, -1
  %prol.iter381.cmp.not = icmp eq i64 %lsr.iv.next602, 0
  br i1 %prol.iter381.cmp.not, label %B188.us.5.prol.loopexit, label %B188.us.5.prol, !llvm.loop !194

B188.us.5.prol.loopexit:                          ; preds = %B188.us.5.prol, %B188.us.5.preheader
  %.568428430.us.5.unr = phi i64 [ %.568428430.us.5.ph, %B188.us.5.preheader ], [ %.575.us.5.prol, %B188.us.5.prol ]
  %271 = sub nsw i64 %.568428430.us.5.ph, %arg.y.2
  %272 = icmp ugt i64 %271, -8
  br i1 %272, label %iter.check229, label %B188.us.5.preheader398

B188.us.5.preheader398:                           ; preds = %B188.us.5.prol.loopexit
  %273 = mul i64 %arg.y.2, 48
  %274 = getelementptr i8, ptr %arg.row.4, i64 %273
  %scevgep567 = getelementptr i8, ptr %274, i64 72
  %275 = getelementptr i8, ptr %arg.F.4, i64 %.idx46946
  %scevgep583 = getelementptr i8, ptr %275, i64 56
  br label %B188.us.5

B188.us.5:                                        ; preds = %B188.us.5, %B188.us.5.preheader398
  %.568428430.us.5 = phi i64 [ %.575.us.5.7, %B188.us.5 ], [ %.568428430.us.5.unr, %B188.us.5.preheader398 ]
  %276 = shl i64 %.568428430.us.5, 3
  %scevgep595 = getelementptr i8, ptr %scevgep583, i64 %276
  %scevgep596 = getelementptr i8, ptr %scevgep595, i64 -56
  %.652.us.5 = load double, ptr %scevgep596, align 8
  %scevgep579 = getelementptr i8, ptr %scevgep567, i64 %276
  %scevgep580 = getelementptr i8, ptr %scevgep579, i64 -56
  store double %.652.us.5, ptr %scevgep580, align 8
  %277 = shl i64 %.568428430.us.5, 3
  %scevgep241 = getelementptr i8, ptr %scevgep583, i64 %277
  %scevgep242 = getelementptr i8, ptr %scevgep241, i64 -48
  %.652.us.5.1 = load double, ptr %scevgep242, align 8
  %278 = shl i64 %.568428430.us.5, 3
  %scevgep229 = getelementptr i8, ptr %scevgep567, i64 %278
  %scevgep230 = getelementptr i8, ptr %scevgep229, i64 -48
  store double %.652.us.5.1, ptr %scevgep230, align 8
  %scevgep239 = getelementptr i8, ptr %scevgep583, i64 %278
  %scevgep240 = getelementptr i8, ptr %scevgep239, i64 -40
  %.652.us.5.2 = load double, ptr %scevgep240, align 8
  %279 = shl i64 %.568428430.us.5, 3
  %scevgep227 = getelementptr i8, ptr %scevgep567, i64 %279
  %scevgep228 = getelementptr i8, ptr %scevgep227, i64 -40
  store double %.652.us.5.2, ptr %scevgep228, align 8
  %scevgep237 = getelementptr i8, ptr %scevgep583, i64 %279
  %scevgep238 = getelementptr i8, ptr %scevgep237, i64 -32
  %.652.us.5.3 = load double, ptr %scevgep238, align 8
  %280 = shl i64 %.568428430.us.5, 3
  %scevgep225 = getelementptr i8, ptr %scevgep567, i64 %280
  %scevgep226 = getelementptr i8, ptr %scevgep225, i64 -32
  store double %.652.us.5.3, ptr %scevgep226, align 8
  %scevgep235 = getelementptr i8, ptr %scevgep583, i64 %280
  %scevgep236 = getelementptr i8, ptr %scevgep235, i64 -24
  %.652.us.5.4 = load double, ptr %scevgep236, align 8
  %281 = shl i64 %.568428430.us.5, 3
  %scevgep223 = getelementptr i8, ptr %scevgep567, i64 %281
  %scevgep224 = getelementptr i8, ptr %scevgep223, i64 -24
  store double %.652.us.5.4, ptr %scevgep224, align 8
  %scevgep233 = getelementptr i8, ptr %scevgep583, i64 %281
  %scevgep234 = getelementptr i8, ptr %scevgep233, i64 -16
  %.652.us.5.5 = load double, ptr %scevgep234, align 8
  %282 = shl i64 %.568428430.us.5, 3
  %scevgep221 = getelementptr i8, ptr %scevgep567, i64 %282
  %scevgep222 = getelementptr i8, ptr %scevgep221, i64 -16
  store double %.652.us.5.5, ptr %scevgep222, align 8
  %scevgep231 = getelementptr i8, ptr %scevgep583, i64 %282
  %scevgep232 = getelementptr i8, ptr %scevgep231, i64 -8
  %.652.us.5.6 = load double, ptr %scevgep232, align 8
  %283 = shl i64 %.568428430.us.5, 3
  %scevgep219 = getelementptr i8, ptr %scevgep567, i64 %283
  %scevgep220 = getelementptr i8, ptr %scevgep219, i64 -8
  store double %.652.us.5.6, ptr %scevgep220, align 8
  %.575.us.5.7 = add nuw nsw i64 %.568428430.us.5, 8
  %.652.us.5.7 = load double, ptr %scevgep595, align 8
  store double %.652.us.5.7, ptr %scevgep579, align 8
  %exitcond460.5.not.7 = icmp eq i64 %arg.y.2, %.575.us.5.7
  br i1 %exitcond460.5.not.7, label %iter.check229.thread, label %B188.us.5, !llvm.loop !195

iter.check229.thread:                             ; preds = %B188.us.5, %vec.epilog.middle.block220, %middle.block207
  %.idx47249.pre-phi = phi i64 [ %255, %middle.block207 ], [ %255, %vec.epilog.middle.block220 ], [ %273, %B188.us.5 ]
  %.3583815243342.ph = phi i64 [ %.3583815243344, %middle.block207 ], [ %.3583815243344, %vec.epilog.middle.block220 ], [ %.3583815243343, %B188.us.5 ]
  %.idx47148 = mul i64 %arg.F.5.1, 48
  %284 = getelementptr i8, ptr %arg.F.4, i64 %.idx47148
  %285 = getelementptr i8, ptr %arg.row.4, i64 %.idx47249.pre-phi
  %286 = getelementptr double, ptr %285, i64 %.3583815243342.ph
  br label %vector.memcheck223

iter.check229:                                    ; preds = %B188.us.5.prol.loopexit
  %287 = icmp ult i64 %arg.y.2, 4
  %.idx471 = mul i64 %arg.F.5.1, 48
  %288 = getelementptr i8, ptr %arg.F.4, i64 %.idx471
  %.idx472 = mul i64 %arg.y.2, 48
  %289 = getelementptr i8, ptr %arg.row.4, i64 %.idx472
  %290 = getelementptr double, ptr %289, i64 %.3583815243343
  br i1 %287, label %B188.us.6.preheader, label %vector.memcheck223

vector.memcheck223:                               ; preds = %iter.check229.thread, %iter.check229
  %291 = phi ptr [ %286, %iter.check229.thread ], [ %290, %iter.check229 ]
  %292 = phi ptr [ %284, %iter.check229.thread ], [ %288, %iter.check229 ]
  %.idx47153 = phi i64 [ %.idx47148, %iter.check229.thread ], [ %.idx471, %iter.check229 ]
  %.358381524334251 = phi i64 [ %.3583815243342.ph, %iter.check229.thread ], [ %.3583815243343, %iter.check229 ]
  %293 = ptrtoint ptr %arg.row.4 to i64
  %294 = ptrtoint ptr %arg.F.4 to i64
  %295 = mul i64 %arg.y.2, 56
  %.neg68 = add i64 %293, 16
  %296 = add i64 %.neg68, %295
  %297 = add i64 %.idx47153, %294
  %298 = sub i64 %296, %297
  %diff.check226 = icmp ult i64 %298, 256
  br i1 %diff.check226, label %B188.us.6.preheader, label %vector.main.loop.iter.check231

vector.main.loop.iter.check231:                   ; preds = %vector.memcheck223
  %min.iters.check230 = icmp samesign ult i64 %arg.y.2, 32
  br i1 %min.iters.check230, label %vec.epilog.ph248, label %vector.ph232

vector.ph232:                                     ; preds = %vector.main.loop.iter.check231
  %n.vec234 = and i64 %arg.y.2, %const
  %299 = getelementptr i8, ptr %arg.row.4, i64 %295
  %scevgep551 = getelementptr i8, ptr %299, i64 208
  %300 = getelementptr i8, ptr %arg.F.4, i64 %.idx47153
  %scevgep559 = getelementptr i8, ptr %300, i64 192
  br label %vector.body235

vector.body235:                                   ; preds = %vector.body235, %vector.ph232
  %index236 = phi i64 [ 0, %vector.ph232 ], [ %index.next241, %vector.body235 ]
  %301 = shl i64 %index236, 3
  %scevgep565 = getelementptr i8, ptr %scevgep559, i64 %301
  %scevgep566 = getelementptr i8, ptr %scevgep565, i64 -192
  %scevgep564 = getelementptr i8, ptr %scevgep565, i64 -128
  %scevgep562 = getelementptr i8, ptr %scevgep565, i64 -64
  %wide.load237 = load <8 x double>, ptr %scevgep566, align 8
  %wide.load238 = load <8 x double>, ptr %scevgep564, align 8
  %wide.load239 = load <8 x double>, ptr %scevgep562, align 8
  %wide.load240 = load <8 x double>, ptr %scevgep565, align 8
  %302 = shl i64 %index236, 3
  %scevgep215 = getelementptr i8, ptr %scevgep551, i64 %302
  %scevgep218 = getelementptr i8, ptr %scevgep215, i64 -192
  %scevgep217 = getelementptr i8, ptr %scevgep215, i64 -128
  %scevgep216 = getelementptr i8, ptr %scevgep215, i64 -64
  store <8 x double> %wide.load237, ptr %scevgep218, align 8
  store <8 x double> %wide.load238, ptr %scevgep217, align 8
  store <8 x double> %wide.load239, ptr %scevgep216, align 8
  store <8 x double> %wide.load240, ptr %scevgep215, align 8
  %index.next241 = add nuw i64 %index236, 32
  %303 = icmp eq i64 %n.vec234, %index.next241
  br i1 %303, label %middle.block242, label %vector.body235, !llvm.loop !196

middle.block242:                                  ; preds = %vector.body235
  %cmp.n243 = icmp eq i64 %arg.y.2, %n.vec234
  br i1 %cmp.n243, label %B238.endif, label %vec.epilog.iter.check246

vec.epilog.iter.check246:                         ; preds = %middle.block242
  %304 = and i64 %arg.y.2, 28
  %min.epilog.iters.check247 = icmp eq i64 %304, 0
  br i1 %min.epilog.iters.check247, label %B188.us.6.preheader, label %vec.epilog.ph248, !prof !9

vec.epilog.ph248:                                 ; preds = %vec.epilog.iter.check246, %vector.main.loop.iter.check231
  %vec.epilog.resume.val244 = phi i64 [ %n.vec234, %vec.epilog.iter.check246 ], [ 0, %vector.main.loop.iter.check231 ]
  %const_mat462 = add i64 %const, 28
  %n.vec250 = and i64 %arg.y.2, %const_mat462
  br label %vec.epilog.vector.body251

vec.epilog.vector.body251:                        ; preds = %vec.epilog.vector.body251, %vec.epilog.ph248
  %index252 = phi i64 [ %vec.epilog.resume.val244, %vec.epilog.ph248 ], [ %index.next254, %vec.epilog.vector.body251 ]
  %305 = shl i64 %index252, 3
  %scevgep550 = getelementptr i8, ptr %292, i64 %305
  %wide.load253 = load <4 x double>, ptr %scevgep550, align 8
  %scevgep549 = getelementptr i8, ptr %291, i64 %305
  store <4 x double> %wide.load253, ptr %scevgep549, align 8
  %index.next254 = add nuw i64 %index252, 4
  %306 = icmp eq i64 %n.vec250, %index.next254
  br i1 %306, label %vec.epilog.middle.block255, label %vec.epilog.vector.body251, !llvm.loop !197

vec.epilog.middle.block255:                       ; preds = %vec.epilog.vector.body251
  %cmp.n256 = icmp eq i64 %arg.y.2, %n.vec250
  br i1 %cmp.n256, label %B238.endif, label %B188.us.6.preheader

B188.us.6.preheader:                              ; preds = %vec.epilog.middle.block255, %vec.epilog.iter.check246, %vector.memcheck223, %iter.check229
  %307 = phi ptr [ %290, %iter.check229 ], [ %291, %vec.epilog.iter.check246 ], [ %291, %vector.memcheck223 ], [ %291, %vec.epilog.middle.block255 ]
  %308 = phi ptr [ %288, %iter.check229 ], [ %292, %vec.epilog.iter.check246 ], [ %292, %vector.memcheck223 ], [ %292, %vec.epilog.middle.block255 ]
  %.idx47154 = phi i64 [ %.idx471, %iter.check229 ], [ %.idx47153, %vec.epilog.iter.check246 ], [ %.idx47153, %vector.memcheck223 ], [ %.idx47153, %vec.epilog.middle.block255 ]
  %.358381524334252 = phi i64 [ %.3583815243343, %iter.check229 ], [ %.358381524334251, %vec.epilog.iter.check246 ], [ %.358381524334251, %vector.memcheck223 ], [ %.358381524334251, %vec.epilog.middle.block255 ]
  %.568428430.us.6.ph = phi i64 [ 0, %iter.check229 ], [ %n.vec234, %vec.epilog.iter.check246 ], [ 0, %vector.memcheck223 ], [ %n.vec250, %vec.epilog.middle.block255 ]
  %309 = sub nsw i64 %arg.y.2, %.568428430.us.6.ph
  %xtraiter382 = and i64 %309, 7
  %lcmp.mod383.not = icmp eq i64 %xtraiter382, 0
  br i1 %lcmp.mod383.not, label %B188.us.6.prol.loopexit, label %B188.us.6.prol.preheader

B188.us.6.prol.preheader:                         ; preds = %B188.us.6.preheader
  br label %B188.us.6.prol

B188.us.6.prol:                                   ; preds = %B188.us.6.prol.preheader, %B188.us.6.prol
  %lsr.iv547 = phi i64 [ %lsr.iv.next548, %B188.us.6.prol ], [ %xtraiter382, %B188.us.6.prol.preheader ]
  %.568428430.us.6.prol = phi i64 [ %.575.us.6.prol, %B188.us.6.prol ], [ %.568428430.us.6.ph, %B188.us.6.prol.preheader ]
  %.575.us.6.prol = add nuw i64 %.568428430.us.6.prol, 1
  %310 = shl i64 %.568428430.us.6.prol, 3
  %scevgep546 = getelementptr i8, ptr %308, i64 %310
  %.652.us.6.prol = load double, ptr %scevgep546, align 8
  %scevgep545 = getelementptr i8, ptr %307, i64 %310
  store double %.652.us.6.prol, ptr %scevgep545, align 8
  %lsr.iv.next548 = add nsw i64 %lsr.iv547, -1
  %prol.iter384.cmp.not = icmp eq i64 %lsr.iv.next548, 0
  br i1 %prol.iter384.cmp.not, label %B188.us.6.prol.loopexit, label %B188.us.6.prol, !llvm.loop !198

B188.us.6.prol.loopexit:                          ; preds = %B188.us.6.prol, %B188.us.6.preheader
  %.568428430.us.6.unr = phi i64 [ %.568428430.us.6.ph, %B188.us.6.preheader ], [ %.575.us.6.prol, %B188.us.6.prol ]
  %311 = sub nsw i64 %.568428430.us.6.ph, %arg.y.2
  %312 = icmp ugt i64 %311, -8
  br i1 %312, label %B238.endif, label %B188.us.6.preheader397

B188.us.6.preheader397:                           ; preds = %B188.us.6.prol.loopexit
  %313 = mul i64 %arg.y.2, 56
  %314 = getelementptr i8, ptr %arg.row.4, i64 %313
  %scevgep513 = getelementptr i8, ptr %314, i64 72
  %315 = getelementptr i8, ptr %arg.F.4, i64 %.idx47154
  %scevgep529 = getelementptr i8, ptr %315, i64 56
  br label %B188.us.6

B188.us.6:                                        ; preds = %B188.us.6, %B188.us.6.preheader397
  %.568428430.us.6 = phi i64 [ %.575.us.6.7, %B188.us.6 ], [ %.568428430.us.6.unr, %B188.us.6.preheader397 ]
  %316 = shl i64 %.568428430.us.6, 3
  %scevgep541 = getelementptr i8, ptr %scevgep529, i64 %316
  %scevgep542 = getelementptr i8, ptr %scevgep541, i64 -56
  %.652.us.6 = load double, ptr %scevgep542, align 8
  %scevgep525 = getelementptr i8, ptr %scevgep513, i64 %316
  %scevgep526 = getelementptr i8, ptr %scevgep525, i64 -56
  store double %.652.us.6, ptr %scevgep526, align 8
  %317 = shl i64 %.568428430.us.6, 3
  %scevgep213 = getelementptr i8, ptr %scevgep529, i64 %317
  %scevgep214 = getelementptr i8, ptr %scevgep213, i64 -48
  %.652.us.6.1 = load double, ptr %scevgep214, align 8
  %318 = shl i64 %.568428430.us.6, 3
  %scevgep201 = getelementptr i8, ptr %scevgep513, i64 %318
  %scevgep202 = getelementptr i8, ptr %scevgep201, i64 -48
  store double %.652.us.6.1, ptr %scevgep202, align 8
  %scevgep211 = getelementptr i8, ptr %scevgep529, i64 %318
  %scevgep212 = getelementptr i8, ptr %scevgep211, i64 -40
  %.652.us.6.2 = load double, ptr %scevgep212, align 8
  %319 = shl i64 %.568428430.us.6, 3
  %scevgep199 = getelementptr i8, ptr %scevgep513, i64 %319
  %scevgep200 = getelementptr i8, ptr %scevgep199, i64 -40
  store double %.652.us.6.2, ptr %scevgep200, align 8
  %scevgep209 = getelementptr i8, ptr %scevgep529, i64 %319
  %scevgep210 = getelementptr i8, ptr %scevgep209, i64 -32
  %.652.us.6.3 = load double, ptr %scevgep210, align 8
  %320 = shl i64 %.568428430.us.6, 3
  %scevgep197 = getelementptr i8, ptr %scevgep513, i64 %320
  %scevgep198 = getelementptr i8, ptr %scevgep197, i64 -32
  store double %.652.us.6.3, ptr %scevgep198, align 8
  %scevgep207 = getelementptr i8, ptr %scevgep529, i64 %320
  %scevgep208 = getelementptr i8, ptr %scevgep207, i64 -24
  %.652.us.6.4 = load double, ptr %scevgep208, align 8
  %321 = shl i64 %.568428430.us.6, 3
  %scevgep195 = getelementptr i8, ptr %scevgep513, i64 %321
  %scevgep196 = getelementptr i8, ptr %scevgep195, i64 -24
  store double %.652.us.6.4, ptr %scevgep196, align 8
  %scevgep205 = getelementptr i8, ptr %scevgep529, i64 %321
  %scevgep206 = getelementptr i8, ptr %scevgep205, i64 -16
  %.652.us.6.5 = load double, ptr %scevgep206, align 8
  %322 = shl i64 %.568428430.us.6, 3
  %scevgep193 = getelementptr i8, ptr %scevgep513, i64 %322
  %scevgep194 = getelementptr i8, ptr %scevgep193, i64 -16
  store double %.652.us.6.5, ptr %scevgep194, align 8
  %scevgep203 = getelementptr i8, ptr %scevgep529, i64 %322
  %scevgep204 = getelementptr i8, ptr %scevgep203, i64 -8
  %.652.us.6.6 = load double, ptr %scevgep204, align 8
  %323 = shl i64 %.568428430.us.6, 3
  %scevgep191 = getelementptr i8, ptr %scevgep513, i64 %323
  %scevgep192 = getelementptr i8, ptr %scevgep191, i64 -8
  store double %.652.us.6.6, ptr %scevgep192, align 8
  %.575.us.6.7 = add nuw nsw i64 %.568428430.us.6, 8
  %.652.us.6.7 = load double, ptr %scevgep541, align 8
  store double %.652.us.6.7, ptr %scevgep525, align 8
  %exitcond460.6.not.7 = icmp eq i64 %arg.y.2, %.575.us.6.7
  br i1 %exitcond460.6.not.7, label %B238.endif, label %B188.us.6, !llvm.loop !199

B238.endif:                                       ; preds = %B188.us.6, %B188.us.6.prol.loopexit, %vec.epilog.middle.block255, %middle.block242, %B154.endif.preheader
  %.358475 = phi i64 [ %.358473, %B154.endif.preheader ], [ %.358381524334251, %middle.block242 ], [ %.358381524334251, %vec.epilog.middle.block255 ], [ %.358381524334252, %B188.us.6.prol.loopexit ], [ %.358381524334252, %B188.us.6 ]
  tail call void @NRT_decref(ptr %arg.F.0)
  %.711 = mul i64 %arg.y.2, 7
  %.715 = add i64 %.358475, %.711
  %.807447.not = icmp slt i64 %arg.par.2, 1
  br i1 %.807447.not, label %B338.endif, label %iter.check265

iter.check265:                                    ; preds = %B238.endif
  %min.iters.check263 = icmp samesign ult i64 %arg.par.2, 8
  br i1 %min.iters.check263, label %B306.preheader, label %vector.memcheck258

vector.memcheck258:                               ; preds = %iter.check265
  %324 = ptrtoint ptr %arg.row.4 to i64
  %325 = ptrtoint ptr %arg.par.4 to i64
  %326 = shl i64 %arg.y.2, 6
  %327 = add i64 %326, %324
  %328 = shl i64 %arg.row.5.0, 3
  %329 = add i64 %327, 16
  %330 = add i64 %329, %328
  %331 = sub i64 %330, %325
  %.fr = freeze i64 %331
  %diff.check261 = icmp ult i64 %.fr, 256
  %332 = sub i64 %329, %325
  %.fr339 = freeze i64 %332
  %diff.check262 = icmp ult i64 %.fr339, 256
  %conflict.rdx = or i1 %diff.check261, %diff.check262
  br i1 %conflict.rdx, label %B306.preheader, label %vector.main.loop.iter.check267

vector.main.loop.iter.check267:                   ; preds = %vector.memcheck258
  %min.iters.check266 = icmp samesign ult i64 %arg.par.2, 32
  br i1 %min.iters.check266, label %vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge, label %vector.ph268

vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge: ; preds = %vector.main.loop.iter.check267
  %.pre = insertelement <8 x i64> poison, i64 %.715, i64 0
  %.pre92 = shufflevector <8 x i64> %.pre, <8 x i64> poison, <8 x i32> zeroinitializer
  %.pre93 = insertelement <8 x i64> poison, i64 %arg.row.5.0, i64 0
  %.pre94 = shufflevector <8 x i64> %.pre93, <8 x i64> poison, <8 x i32> zeroinitializer
  br label %vec.epilog.ph286

vector.ph268:                                     ; preds = %vector.main.loop.iter.check267
  %n.vec270 = and i64 %arg.par.2, %const
  %broadcast.splatinsert = insertelement <8 x i64> poison, i64 %.715, i64 0
  %broadcast.splat = shufflevector <8 x i64> %broadcast.splatinsert, <8 x i64> poison, <8 x i32> zeroinitializer
  %broadcast.splatinsert271 = insertelement <8 x i64> poison, i64 %arg.row.5.0, i64 0
  %broadcast.splat272 = shufflevector <8 x i64> %broadcast.splatinsert271, <8 x i64> poison, <8 x i32> zeroinitializer
  %invariant.op = add <8 x i64> %broadcast.splat, splat (i64 8)
  %invariant.op391 = add <8 x i64> %broadcast.splat, splat (i64 16)
  %invariant.op393 = add <8 x i64> %broadcast.splat, splat (i64 24)
  br label %vector.body273

vector.body273:                                   ; preds = %vector.body273, %vector.ph268
  %index274 = phi i64 [ 0, %vector.ph268 ], [ %index.next279, %vector.body273 ]
  %vec.ind = phi <8 x i64> [ <i64 0, i64 1, i64 2, i64 3, i64 4, i64 5, i64 6, i64 7>, %vector.ph268 ], [ %vec.ind.next, %vector.body273 ]
  %sunkaddr642 = mul i64 %index274, 8
  %sunkaddr643 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr642
  %wide.load275 = load <8 x double>, ptr %sunkaddr643, align 8
  %sunkaddr644 = mul i64 %index274, 8
  %sunkaddr645 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr644
  %sunkaddr646 = getelementptr i8, ptr %sunkaddr645, i64 64
  %wide.load276 = load <8 x double>, ptr %sunkaddr646, align 8
  %sunkaddr647 = mul i64 %index274, 8
  %sunkaddr648 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr647
  %sunkaddr649 = getelementptr i8, ptr %sunkaddr648, i64 128
  %wide.load277 = load <8 x double>, ptr %sunkaddr649, align 8
  %sunkaddr650 = mul i64 %index274, 8
  %sunkaddr651 = getelementptr i8, ptr %arg.par.4, i64 %sunkaddr650
  %sunkaddr652 = getelementptr i8, ptr %sunkaddr651, i64 192
  %wide.load278 = load <8 x double>, ptr %sunkaddr652, align 8
  %333 = add nsw <8 x i64> %vec.ind, %broadcast.splat
  %.reass = add <8 x i64> %invariant.op, %vec.ind
  %.reass392 = add <8 x i64> %invariant.op391, %vec.ind
  %.reass394 = add <8 x i64> %invariant.op393, %vec.ind
  %334 = icmp slt <8 x i64> %333, zeroinitializer
  %335 = icmp slt <8 x i64> %.reass, zeroinitializer
  %336 = icmp slt <8 x i64> %.reass392, zeroinitializer
  %337 = icmp slt <8 x i64> %.reass394, zeroinitializer
  %338 = select <8 x i1> %334, <8 x i64> %broadcast.splat272, <8 x i64> zeroinitializer
  %339 = select <8 x i1> %335, <8 x i64> %broadcast.splat272, <8 x i64> zeroinitializer
  %340 = select <8 x i1> %336, <8 x i64> %broadcast.splat272, <8 x i64> zeroinitializer
  %341 = select <8 x i1> %337, <8 x i64> %broadcast.splat272, <8 x i64> zeroinitializer
  %342 = getelementptr double, ptr %arg.row.4, <8 x i64> %333
  %343 = getelementptr double, ptr %arg.row.4, <8 x i64> %.reass
  %344 = getelementptr double, ptr %arg.row.4, <8 x i64> %.reass392
  %345 = getelementptr double, ptr %arg.row.4, <8 x i64> %.reass394
  %346 = getelementptr double, <8 x ptr> %342, <8 x i64> %338
  %347 = getelementptr double, <8 x ptr> %343, <8 x i64> %339
  %348 = getelementptr double, <8 x ptr> %344, <8 x i64> %340
  %349 = getelementptr double, <8 x ptr> %345, <8 x i64> %341
  tail call void @llvm.masked.scatter.v8f64.v8p0(<8 x double> %wide.load275, <8 x ptr> align 8 %346, <8 x i1> splat (i1 true))
  tail call void @llvm.masked.scatter.v8f64.v8p0(<8 x double> %wide.load276, <8 x ptr> align 8 %347, <8 x i1> splat (i1 true))
  tail call void @llvm.masked.scatter.v8f64.v8p0(<8 x double> %wide.load277, <8 x ptr> align 8 %348, <8 x i1> splat (i1 true))
  tail call void @llvm.masked.scatter.v8f64.v8p0(<8 x double> %wide.load278, <8 x ptr> align 8 %349, <8 x i1> splat (i1 true))
  %index.next279 = add nuw nsw i64 %index274, 32
  %vec.ind.next = add <8 x i64> %vec.ind, splat (i64 32)
  %350 = icmp eq i64 %n.vec270, %index.next279
  br i1 %350, label %middle.block280, label %vector.body273, !llvm.loop !200

middle.block280:                                  ; preds = %vector.body273
  %cmp.n281 = icmp eq i64 %arg.par.2, %n.vec270
  br i1 %cmp.n281, label %B338.endif, label %vec.epilog.iter.check284

vec.epilog.iter.check284:                         ; preds = %middle.block280
  %351 = and i64 %arg.par.2, 24
  %min.epilog.iters.check285 = icmp eq i64 %351, 0
  br i1 %min.epilog.iters.check285, label %B306.preheader, label %vec.epilog.ph286, !prof !201

vec.epilog.ph286:                                 ; preds = %vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge, %vec.epilog.iter.check284
  %broadcast.splat292.pre-phi = phi <8 x i64> [ %.pre94, %vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge ], [ %broadcast.splat272, %vec.epilog.iter.check284 ]
  %broadcast.splat290.pre-phi = phi <8 x i64> [ %.pre92, %vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge ], [ %broadcast.splat, %vec.epilog.iter.check284 ]
  %bc.resume.val282 = phi i64 [ 0, %vector.main.loop.iter.check267.vec.epilog.ph286_crit_edge ], [ %n.vec270, %vec.epilog.iter.check284 ]
  %const_mat = add i64 %const, 24
  %n.vec288 = and i64 %arg.par.2, %const_mat
  %broadcast.splatinsert293 = insertelement <8 x i64> poison, i64 %bc.resume.val282, i64 0
  %broadcast.splat294 = shufflevector <8 x i64> %broadcast.splatinsert293, <8 x i64> poison, <8 x i32> zeroinitializer
  %induction = or disjoint <8 x i64> %broadcast.splat294, <i64 0, i64 1, i64 2, i64 3, i64 4, i64 5, i64 6, i64 7>
  br label %vec.epilog.vector.body295

vec.epilog.vector.body295:                        ; preds = %vec.epilog.vector.body295, %vec.epilog.ph286
  %index296 = phi i64 [ %bc.resume.val282, %vec.epilog.ph286 ], [ %index.next299, %vec.epilog.vector.body295 ]
  %vec.ind297 = phi <8 x i64> [ %induction, %vec.epilog.ph286 ], [ %vec.ind.next300, %vec.epilog.vector.body295 ]
  %352 = shl i64 %index296, 3
  %scevgep504 = getelementptr i8, ptr %arg.par.4, i64 %352
  %wide.load298 = load <8 x double>, ptr %scevgep504, align 8
  %353 = add nsw <8 x i64> %vec.ind297, %broadcast.splat290.pre-phi
  %354 = icmp slt <8 x i64> %353, zeroinitializer
  %355 = select <8 x i1> %354, <8 x i64> %broadcast.splat292.pre-phi, <8 x i64> zeroinitializer
  %356 = getelementptr double, ptr %arg.row.4, <8 x i64> %353
  %357 = getelementptr double, <8 x ptr> %356, <8 x i64> %355
  tail call void @llvm.masked.scatter.v8f64.v8p0(<8 x double> %wide.load298, <8 x ptr> align 8 %357, <8 x i1> splat (i1 true))
  %index.next299 = add nuw i64 %index296, 8
  %vec.ind.next300 = add nuw nsw <8 x i64> %vec.ind297, splat (i64 8)
  %358 = icmp eq i64 %n.vec288, %index.next299
  br i1 %358, label %vec.epilog.middle.block301, label %vec.epilog.vector.body295, !llvm.loop !202

vec.epilog.middle.block301:                       ; preds = %vec.epilog.vector.body295
  %cmp.n302 = icmp eq i64 %arg.par.2, %n.vec288
  br i1 %cmp.n302, label %B338.endif, label %B306.preheader

B306.preheader:                                   ; preds = %vec.epilog.middle.block301, %vec.epilog.iter.check284, %vector.memcheck258, %iter.check265
  %.813446448.ph = phi i64 [ 0, %iter.check265 ], [ 0, %vector.memcheck258 ], [ %n.vec270, %vec.epilog.iter.check284 ], [ %n.vec288, %vec.epilog.middle.block301 ]
  %xtraiter385 = and i64 %arg.par.2, 7
  %lcmp.mod386.not = icmp eq i64 %xtraiter385, 0
  br i1 %lcmp.mod386.not, label %B306.prol.loopexit, label %B306.prol.preheader

B306.prol.preheader:                              ; preds = %B306.preheader
  %359 = shl i64 %arg.y.2, 6
  %360 = shl i64 %arg.row.5.0, 3
  %361 = add nuw nsw i64 %359, 16
  %scevgep180 = getelementptr i8, ptr %arg.row.4, i64 %361
  br label %B306.prol

B306.prol:                                        ; preds = %B306.prol, %B306.prol.preheader
  %lsr.iv502 = phi i64 [ %xtraiter385, %B306.prol.preheader ], [ %lsr.iv.next503, %B306.prol ]
  %.813446448.prol = phi i64 [ %.813446448.ph, %B306.prol.preheader ], [ %.820.prol, %B306.prol ]
  %.820.prol = add nuw nsw i64 %.813446448.prol, 1
  %362 = shl i64 %.813446448.prol, 3
  %scevgep501 = getelementptr i8, ptr %arg.par.4, i64 %362
  %.874.prol = load double, ptr %scevgep501, align 8
  %363 = add i64 %.715, %.813446448.prol
  %.890.prol = icmp slt i64 %363, 0
  %364 = select i1 %.890.prol, i64 %360, i64 0
  %scevgep181 = getelementptr i8, ptr %scevgep180, i64 %364
  %365 = shl i64 %.813446448.prol, 3
  %scevgep182 = getelementptr i8, ptr %scevgep181, i64 %365
  store double %.874.prol, ptr %scevgep182, align 8
  %lsr.iv.next503 = add nsw i64 %lsr.iv502, -1
  %prol.iter387.cmp.not = icmp eq i64 %lsr.iv.next503, 0
  br i1 %prol.iter387.cmp.not, label %B306.prol.loopexit, label %B306.prol, !llvm.loop !203

B306.prol.loopexit:                               ; preds = %B306.prol, %B306.preheader
  %.813446448.unr = phi i64 [ %.813446448.ph, %B306.preheader ], [ %.820.prol, %B306.prol ]
  %366 = sub nsw i64 %.813446448.ph, %arg.par.2
  %367 = icmp ugt i64 %366, -8
  br i1 %367, label %B338.endif, label %B306.preheader396

B306.preheader396:                                ; preds = %B306.prol.loopexit
  %368 = shl i64 %arg.y.2, 6
  %scevgep456 = getelementptr i8, ptr %arg.row.4, i64 %368
  %369 = shl i64 %arg.y.2, 3
  %370 = shl i64 %arg.row.5.0, 3
  br label %B306

B338.endif:                                       ; preds = %B306, %B306.prol.loopexit, %vec.epilog.middle.block301, %middle.block280, %B238.endif
  tail call void @NRT_decref(ptr %arg.row.0)
  tail call void @NRT_decref(ptr %arg.par.0)
  %.1010454.not = icmp slt i64 %arg.ipar.2, 1
  br i1 %.1010454.not, label %B406, label %iter.check310

iter.check310:                                    ; preds = %B338.endif
  %371 = ptrtoint ptr %arg.irow.4 to i64
  %372 = ptrtoint ptr %arg.ipar.4 to i64
  %min.iters.check308 = icmp samesign ult i64 %arg.ipar.2, 4
  %373 = sub i64 %371, %372
  %diff.check307 = icmp ult i64 %373, 256
  %or.cond = select i1 %min.iters.check308, i1 true, i1 %diff.check307
  br i1 %or.cond, label %B380.preheader, label %vector.main.loop.iter.check312

vector.main.loop.iter.check312:                   ; preds = %iter.check310
  %min.iters.check311 = icmp samesign ult i64 %arg.ipar.2, 32
  br i1 %min.iters.check311, label %vec.epilog.ph329, label %vector.ph313

vector.ph313:                                     ; preds = %vector.main.loop.iter.check312
  %n.vec315 = and i64 %arg.ipar.2, %const
  br label %vector.body316

vector.body316:                                   ; preds = %vector.body316, %vector.ph313
  %index317 = phi i64 [ 0, %vector.ph313 ], [ %index.next322, %vector.body316 ]
  %sunkaddr653 = mul i64 %index317, 8
  %sunkaddr654 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr653
  %wide.load318 = load <8 x i64>, ptr %sunkaddr654, align 8
  %sunkaddr655 = mul i64 %index317, 8
  %sunkaddr656 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr655
  %sunkaddr657 = getelementptr i8, ptr %sunkaddr656, i64 64
  %wide.load319 = load <8 x i64>, ptr %sunkaddr657, align 8
  %sunkaddr658 = mul i64 %index317, 8
  %sunkaddr659 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr658
  %sunkaddr660 = getelementptr i8, ptr %sunkaddr659, i64 128
  %wide.load320 = load <8 x i64>, ptr %sunkaddr660, align 8
  %sunkaddr661 = mul i64 %index317, 8
  %sunkaddr662 = getelementptr i8, ptr %arg.ipar.4, i64 %sunkaddr661
  %sunkaddr663 = getelementptr i8, ptr %sunkaddr662, i64 192
  %wide.load321 = load <8 x i64>, ptr %sunkaddr663, align 8
  %sunkaddr664 = mul i64 %index317, 8
  %sunkaddr665 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr664
  store <8 x i64> %wide.load318, ptr %sunkaddr665, align 8
  %sunkaddr666 = mul i64 %index317, 8
  %sunkaddr667 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr666
  %sunkaddr668 = getelementptr i8, ptr %sunkaddr667, i64 64
  store <8 x i64> %wide.load319, ptr %sunkaddr668, align 8
  %sunkaddr669 = mul i64 %index317, 8
  %sunkaddr670 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr669
  %sunkaddr671 = getelementptr i8, ptr %sunkaddr670, i64 128
  store <8 x i64> %wide.load320, ptr %sunkaddr671, align 8
  %sunkaddr672 = mul i64 %index317, 8
  %sunkaddr673 = getelementptr i8, ptr %arg.irow.4, i64 %sunkaddr672
  %sunkaddr674 = getelementptr i8, ptr %sunkaddr673, i64 192
  store <8 x i64> %wide.load321, ptr %sunkaddr674, align 8
  %index.next322 = add nuw nsw i64 %index317, 32
  %374 = icmp eq i64 %n.vec315, %index.next322
  br i1 %374, label %middle.block323, label %vector.body316, !llvm.loop !204

middle.block323:                                  ; preds = %vector.body316
  %cmp.n324 = icmp eq i64 %arg.ipar.2, %n.vec315
  br i1 %cmp.n324, label %B406, label %vec.epilog.iter.check327

vec.epilog.iter.check327:                         ; preds = %middle.block323
  %375 = and i64 %arg.ipar.2, 28
  %min.epilog.iters.check328 = icmp eq i64 %375, 0
  br i1 %min.epilog.iters.check328, label %B380.preheader, label %vec.epilog.ph329, !prof !9

vec.epilog.ph329:                                 ; preds = %vec.epilog.iter.check327, %vector.main.loop.iter.check312
  %vec.epilog.resume.val325 = phi i64 [ %n.vec315, %vec.epilog.iter.check327 ], [ 0, %vector.main.loop.iter.check312 ]
  %const_mat463 = add i64 %const, 28
  %n.vec331 = and i64 %arg.ipar.2, %const_mat463
  br label %vec.epilog.vector.body332

vec.epilog.vector.body332:                        ; preds = %vec.epilog.vector.body332, %vec.epilog.ph329
  %index333 = phi i64 [ %vec.epilog.resume.val325, %vec.epilog.ph329 ], [ %index.next335, %vec.epilog.vector.body332 ]
  %376 = shl i64 %index333, 3
  %scevgep439 = getelementptr i8, ptr %arg.ipar.4, i64 %376
  %wide.load334 = load <4 x i64>, ptr %scevgep439, align 8
  %scevgep438 = getelementptr i8, ptr %arg.irow.4, i64 %376
  store <4 x i64> %wide.load334, ptr %scevgep438, align 8
  %index.next335 = add nuw i64 %index333, 4
  %377 = icmp eq i64 %n.vec331, %index.next335
  br i1 %377, label %vec.epilog.middle.block336, label %vec.epilog.vector.body332, !llvm.loop !205

vec.epilog.middle.block336:                       ; preds = %vec.epilog.vector.body332
  %cmp.n337 = icmp eq i64 %arg.ipar.2, %n.vec331
  br i1 %cmp.n337, label %B406, label %B380.preheader

B380.preheader:                                   ; preds = %vec.epilog.middle.block336, %vec.epilog.iter.check327, %iter.check310
  %.1016453455.ph = phi i64 [ 0, %iter.check310 ], [ %n.vec315, %vec.epilog.iter.check327 ], [ %n.vec331, %vec.epilog.middle.block336 ]
  %378 = sub nsw i64 %arg.ipar.2, %.1016453455.ph
  %xtraiter388 = and i64 %378, 7
  %lcmp.mod389.not = icmp eq i64 %xtraiter388, 0
  br i1 %lcmp.mod389.not, label %B380.prol.loopexit, label %B380.prol.preheader

B380.prol.preheader:                              ; preds = %B380.preheader
  br label %B380.prol

B380.prol:                                        ; preds = %B380.prol.preheader, %B380.prol
  %lsr.iv = phi i64 [ %lsr.iv.next, %B380.prol ], [ %xtraiter388, %B380.prol.preheader ]
  %.1016453455.prol = phi i64 [ %.1023.prol, %B380.prol ], [ %.1016453455.ph, %B380.prol.preheader ]
  %.1023.prol = add nuw i64 %.1016453455.prol, 1
  %379 = shl i64 %.1016453455.prol, 3
  %scevgep437 = getelementptr i8, ptr %arg.ipar.4, i64 %379
  %.1077.prol = load i64, ptr %scevgep437, align 8
  %scevgep436 = getelementptr i8, ptr %arg.irow.4, i64 %379
  store i64 %.1077.prol, ptr %scevgep436, align 8
  %lsr.iv.next = add nsw i64 %lsr.iv, -1
  %prol.iter390.cmp.not = icmp eq i64 %lsr.iv.next, 0
  br i1 %prol.iter390.cmp.not, label %B380.prol.loopexit, label %B380.prol, !llvm.loop !206

B380.prol.loopexit:                               ; preds = %B380.prol, %B380.preheader
  %.1016453455.unr = phi i64 [ %.1016453455.ph, %B380.preheader ], [ %.1023.prol, %B380.prol ]
  %380 = sub nsw i64 %.1016453455.ph, %arg.ipar.2
  %381 = icmp ugt i64 %380, -8
  br i1 %381, label %B406, label %B380.preheader99

B380.preheader99:                                 ; preds = %B380.prol.loopexit
  br label %B380
}

; Function Attrs: mustprogress nocallback nofree nosync nounwind willreturn memory(write)
declare void @llvm.masked.scatter.v8f64.v8p0(<8 x double>, <8 x ptr>, <8 x i1>) #8

attributes #0 = { mustprogress nocallback nofree nounwind willreturn memory(argmem: write) }
attributes #1 = { nofree nounwind memory(read) }
attributes #2 = { nofree norecurse nosync nounwind memory(argmem: readwrite) }
attributes #3 = { noinline }
attributes #4 = { nounwind }
attributes #5 = { mustprogress nofree noinline norecurse nounwind willreturn memory(argmem: readwrite) }
attributes #6 = { mustprogress nocallback nocreateundeforpoison nofree nosync nounwind speculatable willreturn memory(none) }
attributes #7 = { mustprogress nocallback nofree nosync nounwind willreturn memory(none) }
attributes #8 = { mustprogress nocallback nofree nosync nounwind willreturn memory(write) }

!0 = !{!"branch_weights", i32 1, i32 99}
!1 = !{!"branch_weights", i32 49, i32 1}
!2 = distinct !{!2, !3}
!3 = !{!"llvm.loop.peeled.count", i32 1}
!4 = !{!"branch_weights", i32 1, i32 49, i32 49}
!5 = distinct !{!5, !6}
!6 = !{!"llvm.loop.isvectorized", i32 1}
!7 = distinct !{!7, !6, !8}
!8 = !{!"llvm.loop.unroll.runtime.disable"}
!9 = !{!"branch_weights", i32 4, i32 28}
!10 = distinct !{!10, !6, !8}
!11 = distinct !{!11, !12}
!12 = !{!"llvm.loop.unroll.disable"}
!13 = distinct !{!13, !6}
!14 = !{!15, !17}
!15 = distinct !{!15, !16, !"_ZN6charts7solvers4loop7monitorB3v96B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE: %retptr"}
!16 = distinct !{!16, !"_ZN6charts7solvers4loop7monitorB3v96B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE"}
!17 = distinct !{!17, !16, !"_ZN6charts7solvers4loop7monitorB3v96B38c8tJTIeFIjxB2IKSgI4CrvQClQZ6FczSBAA_3dE5ArrayIdLi1E1C7mutable7alignedEd5ArrayIdLi1E1C7mutable7alignedE: %excinfo"}
!18 = !{i1 true}
!19 = distinct !{!19, !6, !8}
!20 = distinct !{!20, !6, !8}
!21 = distinct !{!21, !12}
!22 = distinct !{!22, !6}
!23 = distinct !{!23, !6}
!24 = distinct !{!24, !6, !8}
!25 = distinct !{!25, !6, !8}
!26 = distinct !{!26, !12}
!27 = distinct !{!27, !6, !8}
!28 = distinct !{!28, !6, !8}
!29 = distinct !{!29, !12}
!30 = distinct !{!30, !6, !8}
!31 = distinct !{!31, !6, !8}
!32 = distinct !{!32, !12}
!33 = distinct !{!33, !6, !8}
!34 = distinct !{!34, !6, !8}
!35 = distinct !{!35, !12}
!36 = distinct !{!36, !6}
!37 = distinct !{!37, !6, !8}
!38 = distinct !{!38, !6, !8}
!39 = distinct !{!39, !12}
!40 = distinct !{!40, !6}
!41 = distinct !{!41, !6}
!42 = distinct !{!42, !6, !8}
!43 = distinct !{!43, !6, !8}
!44 = distinct !{!44, !12}
!45 = distinct !{!45, !6}
!46 = distinct !{!46, !6, !8}
!47 = distinct !{!47, !6, !8}
!48 = distinct !{!48, !12}
!49 = distinct !{!49, !6}
!50 = distinct !{!50, !6}
!51 = distinct !{!51, !6, !8}
!52 = distinct !{!52, !6, !8}
!53 = distinct !{!53, !12}
!54 = distinct !{!54, !6}
!55 = distinct !{!55, !6, !8}
!56 = distinct !{!56, !6, !8}
!57 = distinct !{!57, !12}
!58 = distinct !{!58, !6}
!59 = distinct !{!59, !6, !8}
!60 = distinct !{!60, !6, !8}
!61 = distinct !{!61, !12}
!62 = !{!63}
!63 = distinct !{!63, !64}
!64 = distinct !{!64, !"LVerDomain"}
!65 = !{!66}
!66 = distinct !{!66, !64}
!67 = !{!68}
!68 = distinct !{!68, !64}
!69 = !{!70, !71, !63, !66, !72, !73}
!70 = distinct !{!70, !64}
!71 = distinct !{!71, !64}
!72 = distinct !{!72, !64}
!73 = distinct !{!73, !64}
!74 = !{!72}
!75 = !{!70}
!76 = !{!71, !63, !66, !72, !73}
!77 = !{!73}
!78 = !{!71}
!79 = !{!63, !66, !72, !73}
!80 = distinct !{!80, !6, !8}
!81 = distinct !{!81, !12}
!82 = distinct !{!82, !6}
!83 = !{!"branch_weights", i32 39494365, i32 2107989283}
!84 = distinct !{!84, !6}
!85 = distinct !{!85, !6, !8}
!86 = distinct !{!86, !6, !8}
!87 = distinct !{!87, !12}
!88 = distinct !{!88, !6, !8}
!89 = distinct !{!89, !6}
!90 = distinct !{!90, !12}
!91 = distinct !{!91, !6, !8}
!92 = distinct !{!92, !6, !8}
!93 = distinct !{!93, !12}
!94 = distinct !{!94, !6}
!95 = distinct !{!95, !6}
!96 = !{!97}
!97 = distinct !{!97, !98}
!98 = distinct !{!98, !"LVerDomain"}
!99 = !{!100}
!100 = distinct !{!100, !98}
!101 = !{!102}
!102 = distinct !{!102, !98}
!103 = !{!104, !105, !97, !100, !106, !107}
!104 = distinct !{!104, !98}
!105 = distinct !{!105, !98}
!106 = distinct !{!106, !98}
!107 = distinct !{!107, !98}
!108 = !{!106}
!109 = !{!104}
!110 = !{!105, !97, !100, !106, !107}
!111 = !{!107}
!112 = !{!105}
!113 = !{!97, !100, !106, !107}
!114 = distinct !{!114, !6, !8}
!115 = distinct !{!115, !12}
!116 = !{!117}
!117 = distinct !{!117, !118}
!118 = distinct !{!118, !"LVerDomain"}
!119 = !{!120}
!120 = distinct !{!120, !118}
!121 = !{!122}
!122 = distinct !{!122, !118}
!123 = !{!124}
!124 = distinct !{!124, !118}
!125 = !{!126}
!126 = distinct !{!126, !118}
!127 = !{!128}
!128 = distinct !{!128, !118}
!129 = !{!130}
!130 = distinct !{!130, !118}
!131 = !{!132}
!132 = distinct !{!132, !118}
!133 = !{!134}
!134 = distinct !{!134, !118}
!135 = !{!136}
!136 = distinct !{!136, !118}
!137 = !{!138}
!138 = distinct !{!138, !118}
!139 = !{!140}
!140 = distinct !{!140, !118}
!141 = !{!142}
!142 = distinct !{!142, !118}
!143 = !{!144}
!144 = distinct !{!144, !118}
!145 = !{!146}
!146 = distinct !{!146, !118}
!147 = !{!148}
!148 = distinct !{!148, !118}
!149 = !{!150}
!150 = distinct !{!150, !118}
!151 = !{!152, !153, !154, !117, !120, !122, !124, !126, !128, !130, !132, !134, !136, !138, !140, !142, !144, !146, !148}
!152 = distinct !{!152, !118}
!153 = distinct !{!153, !118}
!154 = distinct !{!154, !118}
!155 = !{!152}
!156 = !{!153, !154, !117, !120, !122, !124, !126, !128, !130, !132, !134, !136, !138, !140, !142, !144, !146, !148}
!157 = !{!153}
!158 = !{!154, !117, !120, !122, !124, !126, !128, !130, !132, !134, !136, !138, !140, !142, !144, !146, !148}
!159 = !{!154}
!160 = !{!117, !120, !122, !124, !126, !128, !130, !132, !134, !136, !138, !140, !142, !144, !146, !148}
!161 = distinct !{!161, !6, !8}
!162 = distinct !{!162, !6}
!163 = distinct !{!163, !6, !8}
!164 = distinct !{!164, !12}
!165 = distinct !{!165, !6}
!166 = distinct !{!166, !6, !8}
!167 = distinct !{!167, !6, !8}
!168 = distinct !{!168, !12}
!169 = distinct !{!169, !6}
!170 = distinct !{!170, !6}
!171 = distinct !{!171, !6}
!172 = distinct !{!172, !6, !8}
!173 = distinct !{!173, !6, !8}
!174 = distinct !{!174, !12}
!175 = distinct !{!175, !6}
!176 = distinct !{!176, !6, !8}
!177 = distinct !{!177, !6, !8}
!178 = distinct !{!178, !12}
!179 = distinct !{!179, !6}
!180 = distinct !{!180, !6, !8}
!181 = distinct !{!181, !6, !8}
!182 = distinct !{!182, !12}
!183 = distinct !{!183, !6}
!184 = distinct !{!184, !6, !8}
!185 = distinct !{!185, !6, !8}
!186 = distinct !{!186, !12}
!187 = distinct !{!187, !6}
!188 = distinct !{!188, !6, !8}
!189 = distinct !{!189, !6, !8}
!190 = distinct !{!190, !12}
!191 = distinct !{!191, !6}
!192 = distinct !{!192, !6, !8}
!193 = distinct !{!193, !6, !8}
!194 = distinct !{!194, !12}
!195 = distinct !{!195, !6}
!196 = distinct !{!196, !6, !8}
!197 = distinct !{!197, !6, !8}
!198 = distinct !{!198, !12}
!199 = distinct !{!199, !6}
!200 = distinct !{!200, !6, !8}
!201 = !{!"branch_weights", i32 8, i32 24}
!202 = distinct !{!202, !6, !8}
!203 = distinct !{!203, !12}
!204 = distinct !{!204, !6, !8}
!205 = distinct !{!205, !6, !8}
!206 = distinct !{!206, !12}
